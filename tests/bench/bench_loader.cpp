// Loading an 871K-triangle, ~33 MB OBJ: our loader against tinyobjloader's parse of the same
// file (the yardstick; Debian's libtinyobjloader-dev, used by this benchmark only) and
// OpenMesh's stock OBJ reader, and the peak memory of a process that loads it.
// Run: build/tests/bench/bench_loader [--rounds N] [Google Benchmark flags]
#include <benchmark/benchmark.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <sys/resource.h>
#include <sys/wait.h>
#include <tiny_obj_loader.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "bench_common.h"
#include "renderer/core/elapsed.h"
#include "renderer/mesh/mesh_loader.h"

namespace npr::bench {
namespace {

bool tinyObjParse(const std::string& path, std::size_t& triangles) {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, path.c_str(), nullptr, true);
  triangles = 0;
  for (const auto& s : shapes) triangles += s.mesh.num_face_vertices.size();
  return ok;
}

struct ChildFigures {
  double peakMiB = 0.0, ms = 0.0;
};

// Peak resident memory and time of one load in a fresh process: this benchmark run again
// with --child WHAT PATH (exec, not just fork: a forked child inherits the parent's heap and
// pays copy-on-write faults instead of a new process's first touches).
ChildFigures inFreshProcess(const char* what, const std::string& path) {
  int fds[2];
  if (pipe(fds) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fds[1], 1);
    close(fds[0]);
    execl("/proc/self/exe", "bench_loader", "--child", what, path.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  ChildFigures f;
  char buf[64] = {0};
  const ssize_t n = read(fds[0], buf, sizeof buf - 1);
  close(fds[0]);
  if (n > 0) f.ms = std::atof(buf);
  int status = 0;
  rusage u{};
  wait4(pid, &status, 0, &u);
  f.peakMiB = double(u.ru_maxrss) / 1024.0;
  return f;
}

// The child's side: one load, its time on stdout.
int childLoad(const std::string& what, const std::string& path) {
  const auto t0 = std::chrono::steady_clock::now();
  if (what == "ours" || what == "cached") {
    npr::Result<npr::Mesh> m = npr::loadMesh(path);
    if (!m || m->report.from_cache != (what == "cached")) return 1;
  } else if (what == "tinyobjloader") {
    std::size_t t = 0;
    if (!tinyObjParse(path, t)) return 1;
  }
  std::printf("%.3f\n", npr::msSince(t0));
  return 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// Ours and tinyobjloader alternate, one load each per round, so drift on a shared machine hits
// both alike; medians and their ratio are what to quote.
void interleaved(const std::string& path, int rounds) {
  std::vector<double> ours, tiny;
  std::size_t oursTris = 0, tinyTris = 0;
  for (int r = 0; r < rounds; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    Result<Mesh> m = loadMesh(path);
    ours.push_back(msSince(t0));
    if (!m) { std::fprintf(stderr, "load failed: %s\n", m.error().c_str()); return; }
    oursTris = m->triangleCount();
    t0 = std::chrono::steady_clock::now();
    if (!tinyObjParse(path, tinyTris)) { std::fprintf(stderr, "tinyobjloader failed\n"); return; }
    tiny.push_back(msSince(t0));
  }
  std::printf("interleaved, %d rounds: ours %.0f ms median (%zu triangles, finished mesh: welded, normals, centroids); "
              "tinyobjloader parse %.0f ms median (%zu triangles); ours / tinyobjloader = %.2f\n",
              rounds, median(ours), oursTris, median(tiny), tinyTris, median(ours) / median(tiny));
}

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

void BM_TinyObjLoaderParse(benchmark::State& state) {
  const std::string& path = largeObjPath();
  for (auto _ : state) {
    std::size_t t = 0;
    if (!tinyObjParse(path, t)) state.SkipWithError("tinyobjloader could not read the file");
    benchmark::DoNotOptimize(t);
  }
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
BENCHMARK(BM_TinyObjLoaderParse)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true)->Iterations(1);
BENCHMARK(BM_OpenMeshStockReader)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true)->Iterations(1);

}  // namespace
}  // namespace npr::bench

int main(int argc, char** argv) {
  if (argc == 4 && std::strcmp(argv[1], "--child") == 0) return npr::bench::childLoad(argv[2], argv[3]);
  // Parsing is what is compared with tinyobjloader: the mesh cache stays out of it, and is
  // measured on its own below, in a folder of this run's.
  setenv("NPR_NO_MESH_CACHE", "1", 1);
  int rounds = 7;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--rounds") == 0) rounds = std::max(1, std::atoi(argv[i + 1]));
  const std::string& path = npr::bench::largeObjPath();
  std::printf("file: %s, %.1f MB\n", path.c_str(), double(std::filesystem::file_size(path)) / 1e6);
  // First loads in fresh processes, ours and tinyobjloader alternating.
  std::vector<double> oursMs, tinyMs;
  double oursPeak = 0.0, tinyPeak = 0.0;
  for (int r = 0; r < 5; ++r) {
    const auto ours = npr::bench::inFreshProcess("ours", path);
    const auto tiny = npr::bench::inFreshProcess("tinyobjloader", path);
    oursMs.push_back(ours.ms);
    tinyMs.push_back(tiny.ms);
    oursPeak = std::max(oursPeak, ours.peakMiB);
    tinyPeak = std::max(tinyPeak, tiny.peakMiB);
  }
  const auto empty = npr::bench::inFreshProcess("nothing", path);
  std::printf("first load in a fresh process, 5 each, alternating: ours %.0f ms median and %.0f MiB peak RSS, tinyobjloader "
              "%.0f ms and %.0f MiB; ours / tinyobjloader = %.2f (an idle process: %.0f MiB)\n",
              npr::bench::median(oursMs), oursPeak, npr::bench::median(tinyMs), tinyPeak,
              npr::bench::median(oursMs) / npr::bench::median(tinyMs), empty.peakMiB);
  npr::bench::interleaved(path, rounds);
  {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("npr-bench-cache-" + std::to_string(getpid()));
    setenv("XDG_CACHE_HOME", dir.c_str(), 1);
    unsetenv("NPR_NO_MESH_CACHE");
    (void)npr::loadMesh(path);  // writes the entry
    std::vector<double> times;
    double peak = 0.0;
    for (int r = 0; r < 5; ++r) {
      const auto cached = npr::bench::inFreshProcess("cached", path);
      times.push_back(cached.ms);
      peak = std::max(peak, cached.peakMiB);
    }
    std::printf("reload of the unchanged file from the mesh cache, 5 fresh processes: %.0f ms median, %.0f MiB peak RSS "
                "(0 ms means the reload did not come from the cache)\n", npr::bench::median(times), peak);
    std::filesystem::remove_all(dir);
    setenv("NPR_NO_MESH_CACHE", "1", 1);
  }
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (i + 1 < argc && std::strcmp(argv[i], "--rounds") == 0) { ++i; continue; }
    rest.push_back(argv[i]);
  }
  int n = static_cast<int>(rest.size());
  benchmark::Initialize(&n, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
