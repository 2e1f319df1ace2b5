// Loading an 871K-triangle, ~33 MB OBJ: our loader against OpenMesh's stock OBJ reader, and
// the peak memory of a load. Run: build/tests/bench/bench_loader
#include <benchmark/benchmark.h>

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <cstdio>
#include <filesystem>

#include "bench_common.h"
#include "renderer/mesh/mesh_loader.h"

namespace npr::bench {
namespace {

void BM_LoadObj(benchmark::State& state) {
  const std::string& path = largeObjPath();
  std::size_t triangles = 0;
  for (auto _ : state) {
    Result<Mesh> m = loadMesh(path);
    if (!m) state.SkipWithError(m.error().c_str());
    else triangles = m->triangleCount();
  }
  state.counters["triangles"] = double(triangles);
  state.counters["MB"] = double(std::filesystem::file_size(path)) / 1e6;
}

void BM_OpenMeshStockReader(benchmark::State& state) {
  const std::string& path = largeObjPath();
  for (auto _ : state) {
    TriMesh mesh;
    OpenMesh::IO::Options opt;
    if (!OpenMesh::IO::read_mesh(mesh, path, opt)) state.SkipWithError("OpenMesh could not read the file");
    benchmark::DoNotOptimize(mesh.n_faces());
  }
}

BENCHMARK(BM_LoadObj)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true)->Iterations(1);
BENCHMARK(BM_OpenMeshStockReader)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true)->Iterations(1);

}  // namespace
}  // namespace npr::bench

int main(int argc, char** argv) {
  // Peak memory of one load, measured before anything else has grown the process.
  const std::string& path = npr::bench::largeObjPath();
  const double before = npr::bench::peakRssMiB();
  {
    auto m = npr::loadMesh(path);
    std::printf("one load of %s: %zu triangles in %.0f ms; peak RSS %.0f MiB (process before: %.0f MiB)\n", path.c_str(),
                m ? m->triangleCount() : 0, m ? m->report.load_ms : 0.0, npr::bench::peakRssMiB(), before);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
