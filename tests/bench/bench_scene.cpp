// A scene of N objects against one mesh holding the same triangles (N = 1, 16, 256): frame
// time per palette path, headless, timed interleaved (one frame of each configuration in
// turn). The objects are icospheres in a grid filling the view; the merged mesh is the same
// spheres baked into one mesh. What the ratio measures is the per-object cost: a draw of the
// path per object, per-object lighting state and caches, the stencil path's buckets per
// object. The light moves every frame, so the per-triangle paths do their CPU work each frame.
// Run: build/tests/bench/bench_scene [--size WxH] [--frames N] [--quick]
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app/benchmark/interleaved_timing.h"
#include "bench_common.h"
#include "renderer/core/heap_policy.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/gl/pass_state.h"
#include "renderer/gl/shader_program.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/renderer.h"

using namespace npr;

int main(int argc, char** argv) {
  npr::keepFreedHeapMemory();
  std::optional<bench::ImageBenchArgs> args = bench::parseImageBenchArgs(argc, argv, "bench_scene");
  if (!args) return 2;
  int failure = 0;
  const std::unique_ptr<HeadlessContext> ctx = bench::openBenchContext(failure);  // NPR_GPU, as for the viewer's --gpu
  if (!ctx) return failure;
  auto target = OffscreenTarget::create(args->width, args->height);
  if (!target) return 1;
  auto palette = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/crosshatch/crosshatch.palette");
  if (!palette) return 1;
  std::printf("# bench_scene: %s, %dx%d, %d frames, median ms (interleaved)\n", ctx->info().line().c_str(), args->width, args->height,
              args->frames);
  // cpu: render()'s own time for the objects (the draw calls' submission, where a GPU draws);
  // uniforms, states: in one frame of the objects, the uniform values and pass-state calls sent
  // to GL, against those skipped as already held.
  std::printf("%-8s %-9s %10s %10s %10s %8s %10s %10s %12s %12s\n", "objects", "path", "triangles", "merged", "objects", "ratio",
              "cpu merged", "cpu objects", "uniforms", "states");
  const std::vector<RenderPath> paths = {RenderPath::Stencil, RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth};
  // Icosphere levels with the same triangles in all (20 * 4^level per sphere).
  const std::vector<std::pair<int, int>> scenes = args->quick ? std::vector<std::pair<int, int>>{{16, 3}}
                                                              : std::vector<std::pair<int, int>>{{1, 7}, {16, 5}, {256, 3}};
  for (const auto& [n, level] : scenes) {
    const Mesh sphere = icosphere(level);
    const int side = static_cast<int>(std::lround(std::sqrt(double(n))));
    std::vector<glm::mat4> places;
    for (int i = 0; i < n; ++i) {
      const float cell = 1.4f / float(side);
      const glm::vec3 at(-0.7f + cell * (float(i % side) + 0.5f), 0.7f - cell * (float(i / side) + 0.5f), 0.0f);
      places.push_back(glm::translate(glm::mat4(1.0f), at) * glm::scale(glm::mat4(1.0f), glm::vec3(0.45f * cell)));
    }
    Mesh merged;
    for (const glm::mat4& p : places) {
      const auto base = static_cast<std::uint32_t>(merged.positions.size());
      for (const glm::vec3& v : sphere.positions) merged.positions.push_back(glm::vec3(p * glm::vec4(v, 1.0f)));
      for (std::uint32_t i : sphere.indices) merged.indices.push_back(base + i);
    }
    finalizeMesh(merged);
    auto one = Renderer::create(), many = Renderer::create();
    if (!one || !many) return 1;
    for (Renderer* r : {one->get(), many->get()}) {
      applyDefaultMaterial(r->lighting());
      if (!r->palettes().setMain(*palette)) return 1;
    }
    (*one)->scene().setOnly(&merged);
    for (const glm::mat4& p : places) (*many)->scene().add(sphere, p);
    OrbitCamera cam(0.0f, 0.0f, 3.0f);
    cam.frame(1.0f);
    const CameraMatrices matrices = cam.matrices(float(args->width) / float(args->height));
    int failed = 0, call = 0;
    const std::vector<FrameTiming> t = timeInterleaved(**one, *target, 2 * paths.size(), args->frames, 2,
        [&](std::size_t config, int) {
          RenderSettings s;
          s.path = paths[config / 2];
          Renderer* r = config % 2 ? many->get() : one->get();
          const float angle = 0.6f + 0.002f * float(call++ / 2);
          const float pos[4] = {2.0f * std::cos(angle), 2.5f, 3.0f * std::sin(angle) + 1.0f, 1.0f};
          r->lighting().setModelView(matrices.view);
          if (!r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos)) ++failed;
          return TimedFrame{matrices, s, r};
        }, failed);
    if (failed) {
      std::fprintf(stderr, "bench_scene: %d frame(s) failed\n", failed);
      return 1;
    }
    for (std::size_t p = 0; p < paths.size(); ++p) {
      RenderSettings s;
      s.path = paths[p];
      target->bind();
      const gl::UniformTraffic before = gl::uniformTraffic();
      const gl::StateTraffic statesBefore = gl::stateTraffic();
      if (!(*many)->render(matrices, s, {0, 0, target->width(), target->height()})) return 1;
      const gl::UniformTraffic after = gl::uniformTraffic();
      const gl::StateTraffic statesAfter = gl::stateTraffic();
      char uniforms[32], states[32];
      std::snprintf(uniforms, sizeof uniforms, "%lld/%lld", after.sent - before.sent, after.unchanged - before.unchanged);
      std::snprintf(states, sizeof states, "%lld/%lld", statesAfter.sent - statesBefore.sent, statesAfter.skipped - statesBefore.skipped);
      std::printf("%-8d %-9s %10zu %10.2f %10.2f %7.2fx %10.2f %10.2f %12s %12s\n", n, renderPathName(paths[p]), merged.triangleCount(),
                  t[2 * p].medianMs, t[2 * p + 1].medianMs, t[2 * p + 1].medianMs / t[2 * p].medianMs, t[2 * p].cpuMs, t[2 * p + 1].cpuMs,
                  uniforms, states);
    }
    std::fflush(stdout);
  }
  return 0;
}
