// Mesh intake speed (read + repair of a 400k-triangle scan in each format, against OpenMesh's
// plain read_mesh of the same file in the same run) and last generator speed.
//   build/bin/bench_mesh [--benchmark_filter=...]
// The test scan: a generated EU 42 last of 100k triangles, 1-to-4 subdivided to 400k, with
// scanner noise, written once per format into a fresh temp folder that is removed at exit.
#include <benchmark/benchmark.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <filesystem>
#include <map>
#include <string>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/midpoint_subdivision.hpp"
#include "engine/mesh/openmesh_types.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

const std::filesystem::path& scan_dir() {
  // A fixed name would let two runs (or a leftover of a killed one) share the files.
  static const lastcut::test::TempDir dir("bench-mesh");
  static const bool written = [] {
    const std::filesystem::path& path = dir.path();
    lastcut::LastParams params = lastcut::LastParams::for_eu_size(42, lastcut::FootSide::Left);
    params.surface = lastcut::LastSurface::Remeshed;  // the figures in docs/ were measured on it
    params.target_triangles = 100000;
    params.noise_mm = 0.1;
    const lastcut::TriMesh scan = lastcut::subdivide_midpoint(lastcut::generate_last(params).mesh);
    for (const char* extension : {".stl", ".obj", ".ply", ".off"}) lastcut::write_mesh(path / (std::string("scan400k") + extension), scan);
    return true;
  }();
  (void)written;
  return dir.path();
}

const char* kFormats[] = {".stl", ".obj", ".ply", ".off"};

void BM_ReadAndRepair(benchmark::State& state) {
  const std::filesystem::path file = scan_dir() / (std::string("scan400k") + kFormats[state.range(0)]);
  int triangles = 0;
  for (auto _ : state) {
    const lastcut::MeshIntake intake = lastcut::read_mesh(file);
    triangles = intake.mesh.triangle_count();
    benchmark::DoNotOptimize(triangles);
  }
  state.SetLabel(kFormats[state.range(0)]);
  state.counters["triangles"] = triangles;
}
BENCHMARK(BM_ReadAndRepair)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(3);

// OpenMesh's own reader into a halfedge mesh, no checks and no repair: the baseline.
void BM_OpenMeshReadOnly(benchmark::State& state) {
  const std::filesystem::path file = scan_dir() / (std::string("scan400k") + kFormats[state.range(0)]);
  for (auto _ : state) {
    lastcut::OmMesh mesh;
    OpenMesh::IO::Options options;
    if (!OpenMesh::IO::read_mesh(mesh, file.string(), options)) state.SkipWithError("OpenMesh could not read the scan");
    benchmark::DoNotOptimize(mesh.n_faces());
  }
  state.SetLabel(kFormats[state.range(0)]);
}
BENCHMARK(BM_OpenMeshReadOnly)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(3);

// Second argument: 0 the legacy remeshed surface (the figures in docs/benchmarks-mesh.md), 1 the default Bezier one.
void BM_GenerateLast(benchmark::State& state) {
  lastcut::LastParams params = lastcut::LastParams::for_eu_size(42, lastcut::FootSide::Left);
  params.target_triangles = static_cast<int>(state.range(0));
  params.surface = state.range(1) == 0 ? lastcut::LastSurface::Remeshed : lastcut::LastSurface::Bezier;
  for (auto _ : state) benchmark::DoNotOptimize(lastcut::generate_last(params).mesh.F.rows());
  state.SetLabel(state.range(1) == 0 ? "legacy" : "bezier");
}
BENCHMARK(BM_GenerateLast)->ArgsProduct({{5000, 50000, 200000}, {0, 1}})->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
