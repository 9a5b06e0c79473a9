// `lastcut subdivide`: the bicubic Bezier surface of a quad control mesh (engine/subdiv), sampled
// with n x n quads per control face, written as a quad OBJ.
//   lastcut subdivide last-quads.obj --n 5 -o last.obj
#include <cstdio>
#include <memory>
#include <string>

#include "daemon/cli/commands.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/subdiv/quad_obj.hpp"
#include "engine/subdiv/sample_surface.hpp"

namespace lastcut::cli {
namespace {

struct SubdivideOptions {
  std::string input;
  std::string output;
  int n = 4;
  bool even = false;
};

int run_subdivide(const SubdivideOptions& options) {
  try {
    const QuadMesh control = read_quad_obj(options.input);
    const SubdividedSurface surface = subdivide_bezier(control, options.n, options.even ? SampleSpread::EvenAtExtraordinary : SampleSpread::Uniform);
    write_quad_obj(options.output, surface.quads);
    std::printf("wrote %s: %d control quads at n = %d -> %d quads, %d vertices\n", options.output.c_str(),
                control.quad_count(), options.n, surface.quads.quad_count(), surface.quads.vertex_count());
    return 0;
  } catch (const EngineError& error) {
    std::fprintf(stderr, "lastcut: error: %s\n", error.what());
    return 1;
  }
}

}  // namespace

void add_subdivide_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SubdivideOptions>();
  auto* command = app.add_subcommand("subdivide", "Bezier surface of a quad mesh (OBJ), n x n quads per control face");
  command->add_option("quads", options->input, "Quad control mesh (.obj, 4 corners per face)")->required();
  command->add_option("-n,--n", options->n, "Detail: quads per control face edge (any n >= 1)")->capture_default_str();
  command->add_flag("--even", options->even, "Spread the samples evenly at extraordinary vertices (default: at i/n, as Catmull-Clark)");
  command->add_option("-o,--output", options->output, "Quad OBJ to write")->required();
  command->callback([options, &exit_code] { exit_code = run_subdivide(*options); });
}

}  // namespace lastcut::cli
