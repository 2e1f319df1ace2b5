// Per-triangle lighting + palette matching + bucketing of the 871K-triangle mesh (the
// stencil path's CPU work), by number of lights, specular on/off and thread count; and
// palette matching alone for 2 to 256 entries in each mode.
// Run: build/tests/bench/bench_shading
#include <benchmark/benchmark.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "bench_common.h"
#include "renderer/lines/feature_edges.h"
#include "renderer/lines/line_chains.h"
#include "renderer/palette/palette_matcher.h"
#include "renderer/core/parallel.h"
#include "renderer/shading/triangle_shading.h"
#include "renderer/settings/choice_names.h"

namespace npr::bench {
namespace {

std::vector<glm::vec3> greyLevels(int n) {
  std::vector<glm::vec3> v;
  for (int i = 0; i < n; ++i) v.push_back(glm::vec3(1.0f - float(i) / float(std::max(1, n - 1))));
  return v;
}

// args: lights, specular (0/1), threads (0 = all), bucketed (0/1), point lights (0/1)
void BM_ShadeTriangles(benchmark::State& state) {
  const Mesh& mesh = largeMesh();
  const int lights = int(state.range(0));
  LightingState l;
  for (int i = 0; i < lights; ++i) {
    const float white[4] = {1.0f / float(lights), 1.0f / float(lights), 1.0f / float(lights), 1};
    const float w = state.range(4) ? 1.0f : 0.0f;  // positional (the viewer's default) or directional
    const float dir[4] = {3.0f * std::cos(float(i)), 1.5f, 3.0f * std::sin(float(i)) + 3.0f, w};
    (void)l.Enable(GL_LIGHT0 + GLenum(i));
    (void)l.Lightfv(GL_LIGHT0 + GLenum(i), GL_DIFFUSE, white);
    (void)l.Lightfv(GL_LIGHT0 + GLenum(i), GL_SPECULAR, white);
    (void)l.Lightfv(GL_LIGHT0 + GLenum(i), GL_POSITION, dir);
  }
  if (state.range(1)) {
    const float spec[4] = {0.5f, 0.5f, 0.5f, 1};
    (void)l.Materialfv(GL_FRONT, GL_SPECULAR, spec);
    (void)l.Materialf(GL_FRONT, GL_SHININESS, 24.0f);
  }
  auto matcher = PaletteMatcher::create(greyLevels(10), MatchMode::Intensity, 1.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(1.5f, 1.0f, 2.5f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  TriangleShadingOptions opt;
  opt.buildBuckets = state.range(3) != 0;
  opt.threads = int(state.range(2));
  TriangleShading out;
  for (auto _ : state) {
    shadeTriangles(mesh, l, view, *matcher, opt, out);
    benchmark::DoNotOptimize(out.bucketIndices.data());
  }
  state.counters["triangles/s"] = benchmark::Counter(double(mesh.triangleCount()), benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(std::to_string(lights) + " light(s), specular " + (state.range(1) ? "on" : "off") + ", " +
                 (opt.threads == 1 ? "1 thread" : std::to_string(workerCount()) + " threads") +
                 (opt.buildBuckets ? ", bucketed" : ", not bucketed") + (state.range(4) ? ", point lights" : ", directional"));
}

BENCHMARK(BM_ShadeTriangles)
    ->ArgsProduct({{1, 2, 4, 8}, {0, 1}, {1, 0}, {1}, {0}})
    ->Args({1, 1, 0, 0, 0})  // without bucketing
    ->Args({1, 1, 0, 1, 1})  // one point light with specular: the viewer's default scene
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.5);

// The viewer's default scene (one point light with specular) on the 871K-triangle mesh, with
// the mesh's own materials: 0 = none (today's path), or 1 or 16 materials assigned by region
// (as a model's parts are), optionally with a per-face colour scale (vertex colours or maps).
// Compare with --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true.
void BM_ShadeTrianglesMaterials(benchmark::State& state) {
  const Mesh& mesh = largeMesh();
  const int count = int(state.range(0));
  LightingState l;
  const float pos[4] = {3.0f, 1.5f, 3.0f, 1.0f}, spec[4] = {0.35f, 0.35f, 0.35f, 1};
  (void)l.Lightfv(GL_LIGHT0, GL_POSITION, pos);
  (void)l.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  (void)l.Materialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
  auto matcher = PaletteMatcher::create(greyLevels(10), MatchMode::Intensity, 1.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(1.5f, 1.0f, 2.5f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  TriangleShadingOptions opt;
  opt.buildBuckets = true;
  FaceMaterials fm;
  std::vector<std::uint16_t> faceMaterial;
  std::vector<glm::u8vec4> scale;
  // Material 0 is the lighting state's; the others vary in colour and gloss.
  for (int i = 0; i < count; ++i) {
    Material m = l.front();
    if (i > 0) {
      const float t = float(i) / 16.0f;
      m.ambient = m.diffuse = glm::vec4(0.3f + 0.6f * t, 0.8f - 0.5f * t, 0.5f, 1.0f);
      m.specular = glm::vec4(glm::vec3(i % 3 == 0 ? 0.0f : 0.4f), 1.0f);
      m.shininess = 8.0f + 4.0f * float(i);
    }
    fm.materials.push_back(m);
  }
  if (count > 1) {
    faceMaterial.resize(mesh.triangleCount());
    for (std::size_t f = 0; f < faceMaterial.size(); ++f)
      faceMaterial[f] = std::uint16_t(int((mesh.faceCentroids[f].x + 1.0f) * 8.0f + (mesh.faceCentroids[f].y + 1.0f) * 4.0f) % count);
    fm.faceMaterial = faceMaterial.data();
  }
  if (state.range(1)) {
    scale.resize(mesh.triangleCount());
    for (std::size_t f = 0; f < scale.size(); ++f) scale[f] = glm::u8vec4(glm::vec3(128.0f + 127.0f * std::fabs(mesh.faceNormals[f].x)), 255);
    fm.faceScale = scale.data();
  }
  TriangleShading out;
  for (auto _ : state) {
    shadeTriangles(mesh, l, view, *matcher, opt, out, count > 0 ? &fm : nullptr);
    benchmark::DoNotOptimize(out.bucketIndices.data());
  }
  state.counters["triangles/s"] = benchmark::Counter(double(mesh.triangleCount()), benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(count == 0 ? std::string("no materials (the lighting state's)")
                            : std::to_string(count) + " material(s)" + (state.range(1) ? ", per-face colour" : ""));
}
BENCHMARK(BM_ShadeTrianglesMaterials)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({16, 0})
    ->Args({16, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.5);

// args: palette size, mode
void BM_Match(benchmark::State& state) {
  const int n = int(state.range(0));
  const MatchMode mode = static_cast<MatchMode>(state.range(1));
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec3> avg;
  for (int i = 0; i < n; ++i) avg.push_back({u(rng), u(rng), u(rng)});
  auto m = PaletteMatcher::create(avg, mode, 1.0f);
  std::vector<glm::vec3> queries(4096);
  for (auto& q : queries) q = {u(rng), u(rng), u(rng)};
  int sum = 0;
  for (auto _ : state)
    for (const auto& q : queries) sum += m->match(q);
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(queries.size()));
  state.SetLabel(std::string(choiceName(mode)) + ", " + std::to_string(n) + " entries");
}

// Silhouettes of the 871K-triangle mesh for a new eye position (what a view change costs).
void BM_Silhouettes(benchmark::State& state) {
  FeatureEdges edges(largeMesh());
  float angle = 0.0f;
  std::size_t n = 0;
  for (auto _ : state) {
    angle += 0.01f;
    n = edges.silhouettes(glm::vec3(3.0f * std::cos(angle), 1.0f, 3.0f * std::sin(angle))).size();
  }
  state.counters["silhouette_edges"] = double(n);
}
BENCHMARK(BM_Silhouettes)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

// The same silhouettes chained into strokes with their parameter carried from the previous
// view (lines/line_chains.h): what a view change costs with chains, against BM_Silhouettes.
void BM_SilhouetteChains(benchmark::State& state) {
  FeatureEdges edges(largeMesh());
  LineChains chains(1e-3f);
  float angle = 0.0f;
  std::size_t n = 0;
  for (auto _ : state) {
    angle += 0.01f;
    n = chains.update(edges.silhouettes(glm::vec3(3.0f * std::cos(angle), 1.0f, 3.0f * std::sin(angle))), 0.01f).size();
  }
  state.counters["silhouette_edges"] = double(n);
  state.counters["chains"] = double(chains.coherence().chains);
}
BENCHMARK(BM_SilhouetteChains)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

// Creases and boundaries, once per mesh: the adjacency build included.
void BM_FeatureEdgesBuild(benchmark::State& state) {
  for (auto _ : state) {
    FeatureEdges edges(largeMesh());
    benchmark::DoNotOptimize(edges.staticLines(60.0f).size());
  }
}
BENCHMARK(BM_FeatureEdgesBuild)->Unit(benchmark::kMillisecond)->Iterations(2);

BENCHMARK(BM_Match)->ArgsProduct({{2, 10, 30, 64, 256}, {0, 1, 2}});

}  // namespace
}  // namespace npr::bench

BENCHMARK_MAIN();
