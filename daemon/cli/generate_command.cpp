// `lastcut generate`: writes a synthetic shoe-last scan (engine/lastgen) for trying the pipeline,
// for tests and for demonstrations without a scanner.
//   lastcut generate -o last.stl --size 42 --side left --noise 0.2 --random-pose --seed 3
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "daemon/cli/commands.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"

namespace lastcut::cli {
namespace {

struct GenerateOptions {
  std::string output;
  std::string pose_output;
  int eu_size = 42;
  std::string side = "left";
  int triangles = 50000;
  double noise_mm = 0.0;
  int holes = 0;
  int seams = 0;
  double seam_step_mm = 0.2;
  bool random_pose = false;
  uint64_t seed = 1;
  std::string surface = "legacy";
  std::string noise_kind = "normal";
};

bool has_mesh_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".stl" || extension == ".obj" || extension == ".ply" || extension == ".off";
}

void write_pose(const std::string& path, const GeneratedLast& last, const GenerateOptions& options) {
  nlohmann::json matrix = nlohmann::json::array();
  for (int row = 0; row < 4; ++row) {
    nlohmann::json values = nlohmann::json::array();
    for (int col = 0; col < 4; ++col) values.push_back(last.canonical_to_scan.matrix()(row, col));
    matrix.push_back(values);
  }
  const nlohmann::json document{{"canonical_to_scan", matrix}, {"eu_size", options.eu_size}, {"side", options.side},
                                {"seed", options.seed}, {"units", "mm"}};
  std::ofstream out(path);
  out << document.dump(2) << "\n";
  if (!out) throw EngineError("cannot write " + path);
}

int run_generate(const GenerateOptions& options) {
  if (!has_mesh_extension(options.output)) {
    std::fprintf(stderr, "lastcut: error: output must end in .stl, .obj, .ply or .off: %s\n", options.output.c_str());
    return 2;
  }
  try {
    LastParams params = LastParams::for_eu_size(options.eu_size, options.side == "right" ? FootSide::Right : FootSide::Left);
    params.target_triangles = options.triangles;
    params.noise_mm = options.noise_mm;
    params.holes = options.holes;
    params.seams = options.seams;
    params.seam_step_mm = options.seam_step_mm;
    params.random_pose = options.random_pose;
    params.seed = options.seed;
    params.noise_kind = options.noise_kind == "isotropic" ? ScanNoise::Isotropic : ScanNoise::AlongNormal;
    params.surface = options.surface == "bezier"   ? LastSurface::Bezier
                     : options.surface == "lofted" ? LastSurface::Lofted
                                                   : LastSurface::Remeshed;  // legacy, remeshed
    const GeneratedLast last = generate_last(params);
    write_mesh(options.output, last.mesh);
    if (!options.pose_output.empty()) write_pose(options.pose_output, last, options);
    const Eigen::Vector3d size = bounding_box_size(last.mesh);
    std::printf("wrote %s: EU %d %s last, %.1f mm long, %d triangles%s%s%s%s (bounding box %.1f x %.1f x %.1f mm)\n",
                options.output.c_str(), options.eu_size, options.side.c_str(), params.length_mm,
                last.mesh.triangle_count(), options.noise_mm > 0 ? ", noise" : "", options.holes > 0 ? ", holes" : "",
                options.seams > 0 ? ", stitching seams" : "", options.random_pose ? ", random pose" : "", size.x(), size.y(), size.z());
    return 0;
  } catch (const EngineError& error) {
    std::fprintf(stderr, "lastcut: error: %s\n", error.what());
    return 1;
  }
}

}  // namespace

void add_generate_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<GenerateOptions>();
  auto* command = app.add_subcommand("generate", "Write a synthetic shoe-last scan (parametric last, optional scanner noise, holes, seams, pose)");
  command->add_option("-o,--output", options->output, "Mesh file to write: .stl (binary), .obj, .ply or .off")->required();
  command->add_option("--size", options->eu_size, "EU (Paris point) size")->check(CLI::Range(35, 47))->capture_default_str();
  command->add_option("--side", options->side, "Which foot")->check(CLI::IsMember({"left", "right"}))->capture_default_str();
  command->add_option("--triangles", options->triangles, "Triangle count of the mesh")
      ->check(CLI::Range(2000, 2000000))
      ->capture_default_str();
  command->add_option("--noise", options->noise_mm, "Scanner noise, Gaussian sigma in mm (see --noise-kind)")
      ->check(CLI::Range(0.0, 2.0))
      ->capture_default_str();
  command->add_option("--holes", options->holes, "Small scan holes to punch (never on the top cut)")
      ->check(CLI::Range(0, 50))
      ->capture_default_str();
  command->add_option("--seams", options->seams,
                      "Stitching seams: planes where two scan passes were merged (edges split there, one pass misregistered)")
      ->check(CLI::Range(0, 8))
      ->capture_default_str();
  command->add_option("--seam-step", options->seam_step_mm, "Misregistration of the passes at a seam, mm")
      ->check(CLI::Range(0.0, 2.0))
      ->capture_default_str();
  command->add_flag("--random-pose", options->random_pose, "Rotate and move the scan arbitrarily");
  command->add_option("--seed", options->seed, "Random seed: the same seed gives the same file")->capture_default_str();
  command->add_option("--noise-kind", options->noise_kind,
                      "normal (each vertex moved along its normal) or isotropic (in all three directions, as scanners err)")
      ->check(CLI::IsMember({"normal", "isotropic"}))
      ->capture_default_str();
  command->add_option("--surface", options->surface,
                      "legacy (remeshed implicit solid; 'remeshed' is the same), bezier (C2 Bezier surface, sharp flat top "
                      "cut) or lofted (rings across the last, slivers at the heel and toe poles, as scanner exports mesh)")
      ->check(CLI::IsMember({"bezier", "legacy", "remeshed", "lofted"}))
      ->capture_default_str();
  command->add_option("--pose-out", options->pose_output, "Also write the canonical-to-scan transform as JSON");
  command->callback([options, &exit_code] { exit_code = run_generate(*options); });
}

}  // namespace lastcut::cli
