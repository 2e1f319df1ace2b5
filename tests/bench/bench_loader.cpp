// Loading an 871K-triangle, ~33 MB OBJ: our loader against tinyobjloader's parse of the same
// file (the issue's yardstick; Debian's libtinyobjloader-dev, used by this benchmark only) and
// OpenMesh's stock OBJ reader, and the peak memory of a process that loads it. Then glTF: a
// GLB of the same 871K triangles and a GLB of 256 nodes instancing 16 meshes, loaded as a
// scene by ours and by assimp (Debian's libassimp-dev, this benchmark only) with the steps a
// viewer needs of it (triangulated, identical vertices joined, smooth normals).
// Run: build/tests/bench/bench_loader [--rounds N] [Google Benchmark flags]
#include <benchmark/benchmark.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
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
#include "renderer/mesh/mesh_generators.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/mesh/scene_loader.h"

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
// pays copy-on-write faults instead of a new process's first touches). The child reports its
// own peak (VmHWM, which exec starts afresh): the rusage of a forked child also counts the
// parent's pages it held before exec, so every small load read as the parent's size.
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
  double kib = 0.0;
  if (n > 0 && std::sscanf(buf, "%lf %lf", &f.ms, &kib) == 2) f.peakMiB = kib / 1024.0;
  int status = 0;
  waitpid(pid, &status, 0);
  return f;
}

// A GLB of `meshes`, each placed by the nodes that name it (`nodes`: mesh index and
// translation): one buffer of float positions and 32-bit indices.
void writeGlb(const std::string& path, const std::vector<const Mesh*>& meshes, const std::vector<std::pair<int, glm::vec3>>& nodes) {
  std::string bin, json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)";
  for (std::size_t i = 0; i < nodes.size(); ++i) json += (i ? "," : "") + std::to_string(i);
  json += R"(]}],"nodes":[)";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const glm::vec3& t = nodes[i].second;
    json += (i ? "," : "") + std::string(R"({"mesh":)") + std::to_string(nodes[i].first) + R"(,"translation":[)" + std::to_string(t.x) + "," +
            std::to_string(t.y) + "," + std::to_string(t.z) + "]}";
  }
  std::string meshJson, accessors, views;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = *meshes[m];
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const std::size_t posAt = bin.size();
    bin.append(reinterpret_cast<const char*>(mesh.positions.data()), mesh.positions.size() * sizeof(glm::vec3));
    const std::size_t idxAt = bin.size();
    bin.append(reinterpret_cast<const char*>(mesh.indices.data()), mesh.indices.size() * 4);
    const std::string k = std::to_string(2 * m), k1 = std::to_string(2 * m + 1);
    meshJson += (m ? "," : "") + std::string(R"({"primitives":[{"attributes":{"POSITION":)") + k + R"(},"indices":)" + k1 + "}]}";
    accessors += (m ? "," : "") + std::string(R"({"bufferView":)") + k + R"(,"componentType":5126,"count":)" + std::to_string(mesh.positions.size()) +
                 R"(,"type":"VEC3","min":[)" + std::to_string(lo.x) + "," + std::to_string(lo.y) + "," + std::to_string(lo.z) + R"(],"max":[)" +
                 std::to_string(hi.x) + "," + std::to_string(hi.y) + "," + std::to_string(hi.z) + "]}," + R"({"bufferView":)" + k1 +
                 R"(,"componentType":5125,"count":)" + std::to_string(mesh.indices.size()) + R"(,"type":"SCALAR"})";
    views += (m ? "," : "") + std::string(R"({"buffer":0,"byteOffset":)") + std::to_string(posAt) + R"(,"byteLength":)" +
             std::to_string(idxAt - posAt) + R"(},{"buffer":0,"byteOffset":)" + std::to_string(idxAt) + R"(,"byteLength":)" +
             std::to_string(mesh.indices.size() * 4) + "}";
  }
  json += R"(],"meshes":[)" + meshJson + R"(],"accessors":[)" + accessors + R"(],"bufferViews":[)" + views + R"(],"buffers":[{"byteLength":)" +
          std::to_string(bin.size()) + "}]}";
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  auto u32 = [](std::string& out, std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  std::string glb = "glTF";
  u32(glb, 2);
  u32(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  u32(glb, static_cast<std::uint32_t>(json.size()));
  glb += "JSON" + json;
  u32(glb, static_cast<std::uint32_t>(bin.size()));
  glb += std::string("BIN\0", 4) + bin;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f) {
    std::fwrite(glb.data(), 1, glb.size(), f);
    std::fclose(f);
  }
}

// The two GLBs, written once into the temp folder.
const std::string& largeGlbPath() {
  static const std::string path = [] {
    const auto p = (std::filesystem::temp_directory_path() / "npr-bench-torus-871k.glb").string();
    if (!std::filesystem::exists(p)) writeGlb(p, {&largeMesh()}, {{0, glm::vec3(0.0f)}});
    return p;
  }();
  return path;
}
const std::string& multiNodeGlbPath() {
  static const std::string path = [] {
    const auto p = (std::filesystem::temp_directory_path() / "npr-bench-256-nodes.glb").string();
    if (!std::filesystem::exists(p)) {
      std::vector<Mesh> spheres;
      for (int i = 0; i < 16; ++i) spheres.push_back(icosphere(2 + i % 3));
      std::vector<const Mesh*> meshes;
      for (const Mesh& m : spheres) meshes.push_back(&m);
      std::vector<std::pair<int, glm::vec3>> nodes;
      for (int i = 0; i < 256; ++i) nodes.push_back({i % 16, glm::vec3(float(i % 16) * 2.5f, float(i / 16) * 2.5f, 0.0f)});
      writeGlb(p, meshes, nodes);
    }
    return p;
  }();
  return path;
}

bool assimpLoad(const std::string& path, std::size_t& triangles) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals);
  if (!scene) return false;
  triangles = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) triangles += scene->mMeshes[i]->mNumFaces;
  return true;
}

// The child's side: one load, its time on stdout.
int childLoad(const std::string& what, const std::string& path) {
  const auto t0 = std::chrono::steady_clock::now();
  if (what == "scene") {
    npr::Result<npr::LoadedScene> s = npr::loadScene(path);
    if (!s) return 1;
  } else if (what == "assimp") {
    std::size_t t = 0;
    if (!assimpLoad(path, t)) return 1;
  } else if (what == "ours" || what == "cached") {
    npr::Result<npr::Mesh> m = npr::loadMesh(path);
    if (!m || m->report.from_cache != (what == "cached")) return 1;
  } else if (what == "tinyobjloader") {
    std::size_t t = 0;
    if (!tinyObjParse(path, t)) return 1;
  }
  const double ms = npr::msSince(t0);
  long hwm = 0;
  if (std::FILE* f = std::fopen("/proc/self/status", "r")) {
    char line[256];
    while (std::fgets(line, sizeof line, f))
      if (std::sscanf(line, "VmHWM: %ld kB", &hwm) == 1) break;
    std::fclose(f);
  }
  std::printf("%.3f %ld\n", ms, hwm);
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
  // glTF: ours (as a scene) against assimp, each in fresh processes, alternating.
  for (const std::string& glb : {npr::bench::largeGlbPath(), npr::bench::multiNodeGlbPath()}) {
    std::vector<double> ours, theirs;
    double oursPeak = 0.0, theirPeak = 0.0;
    for (int r = 0; r < 5; ++r) {
      const auto a = npr::bench::inFreshProcess("scene", glb);
      const auto b = npr::bench::inFreshProcess("assimp", glb);
      ours.push_back(a.ms);
      theirs.push_back(b.ms);
      oursPeak = std::max(oursPeak, a.peakMiB);
      theirPeak = std::max(theirPeak, b.peakMiB);
    }
    npr::Result<npr::LoadedScene> s = npr::loadScene(glb);
    std::size_t assimpTris = 0;
    (void)npr::bench::assimpLoad(glb, assimpTris);
    std::printf("%s (%.1f MB, %zu objects, %zu triangles; assimp %zu): ours %.0f ms median and %.0f MiB peak RSS, assimp %.0f ms and "
                "%.0f MiB; ours / assimp = %.2f (5 fresh processes each, alternating)\n",
                std::filesystem::path(glb).filename().c_str(), double(std::filesystem::file_size(glb)) / 1e6, s ? s->objects.size() : 0,
                s ? std::size_t(s->report.triangles) : 0, assimpTris, npr::bench::median(ours), oursPeak, npr::bench::median(theirs),
                theirPeak, npr::bench::median(ours) / npr::bench::median(theirs));
    std::fflush(stdout);
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
