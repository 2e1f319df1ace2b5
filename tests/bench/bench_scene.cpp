// A scene of N objects against one mesh holding the same triangles (N = 1, 16, 256, or
// --objects N): frame time per palette path, headless, timed interleaved (one frame of each
// configuration in turn). Every other object is one of four shared spheres (instances), the
// rest spheres stretched each its own way, each in one of four materials, in a grid filling
// the view; the merged mesh is the same spheres baked into one mesh. Columns: the objects as
// the renderer draws them (small static ones merged into batches, scene/scene_batches.h),
// each drawn alone (RenderTuning::batchObjects off), and with every 100th object in a palette
// of its own (drawn alone); uniforms, state calls and draws are one frame of the objects. The
// light moves every frame, so the per-triangle paths do their CPU work each frame.
// Run: build/tests/bench/bench_scene [--size WxH] [--frames N] [--quick] [--objects N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
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
#include "support/test_util.h"

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
  std::printf("%-8s %-9s %10s %10s %10s %8s %10s %8s %10s %8s %10s %10s %12s %12s %8s\n", "objects", "path", "triangles", "merged",
              "objects", "ratio", "alone", "ratio", "palettes", "ratio", "cpu merged", "cpu objects", "uniforms", "states", "draws");
  const std::vector<RenderPath> paths = {RenderPath::Stencil, RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth};
  // Icosphere levels with the same triangles in all (20 * 4^level per sphere).
  std::vector<std::pair<int, int>> scenes = args->quick ? std::vector<std::pair<int, int>>{{16, 3}}
                                                        : std::vector<std::pair<int, int>>{{1, 7}, {16, 5}, {256, 3}};
  // --objects N: that many, each of the level whose triangles make the scene nearest 327,680.
  if (args->objects > 0) {
    const double perObject = 327680.0 / 20.0 / double(args->objects);
    scenes = {{args->objects, std::clamp(int(std::lround(std::log(std::max(perObject, 1.0)) / std::log(4.0))), 0, 7)}};
  }
  auto wood = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/wood/wood.palette");
  if (!wood) return 1;
  // Four materials, one per shape.
  const glm::vec3 diffuse[4] = {{0.8f, 0.3f, 0.2f}, {0.3f, 0.7f, 0.3f}, {0.3f, 0.4f, 0.9f}, {0.7f, 0.7f, 0.7f}};
  for (const auto& [n, level] : scenes) {
    // Every other object one of four shared shapes (instances), the rest shapes of their own
    // (each sphere stretched its own way); each shape in one of four materials.
    std::deque<Mesh> shapes;
    for (int k = 0; k < 4; ++k) shapes.push_back(test::sphereInMaterial(level, "m" + std::to_string(k), diffuse[k]));
    const int side = static_cast<int>(std::ceil(std::sqrt(double(n))));
    std::vector<glm::mat4> places;
    std::vector<const Mesh*> meshes;
    for (int i = 0; i < n; ++i) {
      const float cell = 1.4f / float(side);
      const glm::vec3 at(-0.7f + cell * (float(i % side) + 0.5f), 0.7f - cell * (float(i / side) + 0.5f), 0.0f);
      places.push_back(glm::translate(glm::mat4(1.0f), at) * glm::scale(glm::mat4(1.0f), glm::vec3(0.45f * cell)));
      if (n == 1 || i % 2 == 0) {
        meshes.push_back(&shapes[std::size_t(i / 2) % 4]);
        continue;
      }
      Mesh own = shapes[std::size_t(i / 2) % 4];
      const float stretch = 0.75f + 0.5f * float((i * 7919) % 101) / 100.0f;
      for (glm::vec3& v : own.positions) v.y *= stretch;
      finalizeMesh(own);
      shapes.push_back(std::move(own));
      meshes.push_back(&shapes.back());
    }
    Mesh merged;
    merged.materials = {shapes[0].materials[0], shapes[1].materials[0], shapes[2].materials[0], shapes[3].materials[0]};
    for (std::size_t i = 0; i < places.size(); ++i) {
      const auto base = static_cast<std::uint32_t>(merged.positions.size());
      for (const glm::vec3& v : meshes[i]->positions) merged.positions.push_back(glm::vec3(places[i] * glm::vec4(v, 1.0f)));
      for (std::uint32_t k : meshes[i]->indices) merged.indices.push_back(base + k);
      const auto material = static_cast<std::uint16_t>(std::find_if(merged.materials.begin(), merged.materials.end(), [&](const MeshMaterial& m) {
                                                         return m.name == meshes[i]->materials[0].name;
                                                       }) - merged.materials.begin());
      merged.faceMaterials.insert(merged.faceMaterials.end(), meshes[i]->triangleCount(), material);
    }
    finalizeMesh(merged);
    // The merged mesh; the objects; the objects each drawn alone (RenderTuning::batchObjects
    // off); the objects with every 100th in a palette of its own.
    std::vector<std::unique_ptr<Renderer>> r;
    for (int k = 0; k < 4; ++k) {
      auto made = Renderer::create();
      if (!made) return 1;
      applyDefaultMaterial((*made)->lighting());
      if (!(*made)->palettes().setMain(*palette)) return 1;
      r.push_back(std::move(*made));
    }
    r[0]->scene().setOnly(&merged);
    for (int k = 1; k < 4; ++k)
      for (std::size_t i = 0; i < places.size(); ++i) {
        const ModelId id = r[std::size_t(k)]->scene().add(*meshes[i], places[i]);
        if (k == 3 && i % 100 == 50 && !r[3]->scene().setPalette(id, *wood)) return 1;
      }
    OrbitCamera cam(0.0f, 0.0f, 3.0f);
    cam.frame(1.0f);
    const CameraMatrices matrices = cam.matrices(float(args->width) / float(args->height));
    auto settingsFor = [&](std::size_t p, std::size_t k) {
      RenderSettings s;
      s.path = paths[p];
      s.tuning.batchObjects = k != 2;
      return s;
    };
    // The first frame of each (the batches made, the buffers uploaded), outside the timing.
    target->bind();
    for (std::size_t k = 0; k < 4; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      if (!r[k]->render(matrices, settingsFor(3, k), {0, 0, target->width(), target->height()})) return 1;
      glFinish();
      if (k == 1) std::printf("# %d objects: first frame %.0f ms (batches made: %zu)\n", n,
                              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count(), r[1]->scene().batchCount());
    }
    int failed = 0, call = 0;
    const std::vector<FrameTiming> t = timeInterleaved(*r[0], *target, 4 * paths.size(), args->frames, 2,
        [&](std::size_t config, int) {
          const std::size_t k = config % 4;
          Renderer* renderer = r[k].get();
          const float angle = 0.6f + 0.002f * float(call++ / 4);
          const float pos[4] = {2.0f * std::cos(angle), 2.5f, 3.0f * std::sin(angle) + 1.0f, 1.0f};
          renderer->lighting().setModelView(matrices.view);
          if (!renderer->lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos)) ++failed;
          return TimedFrame{matrices, settingsFor(config / 4, k), renderer};
        }, failed);
    if (failed) {
      std::fprintf(stderr, "bench_scene: %d frame(s) failed\n", failed);
      return 1;
    }
    for (std::size_t p = 0; p < paths.size(); ++p) {
      target->bind();
      const gl::UniformTraffic before = gl::uniformTraffic();
      const gl::StateTraffic statesBefore = gl::stateTraffic();
      if (!r[1]->render(matrices, settingsFor(p, 1), {0, 0, target->width(), target->height()})) return 1;
      const int draws = r[1]->stats().drawCalls;
      const gl::UniformTraffic after = gl::uniformTraffic();
      const gl::StateTraffic statesAfter = gl::stateTraffic();
      char uniforms[32], states[32];
      std::snprintf(uniforms, sizeof uniforms, "%lld/%lld", after.sent - before.sent, after.unchanged - before.unchanged);
      std::snprintf(states, sizeof states, "%lld/%lld", statesAfter.sent - statesBefore.sent, statesAfter.skipped - statesBefore.skipped);
      const double m = t[4 * p].medianMs;
      std::printf("%-8d %-9s %10zu %10.2f %10.2f %7.2fx %10.2f %7.2fx %10.2f %7.2fx %10.2f %10.2f %12s %12s %8d\n", n,
                  renderPathName(paths[p]), merged.triangleCount(), m, t[4 * p + 1].medianMs, t[4 * p + 1].medianMs / m,
                  t[4 * p + 2].medianMs, t[4 * p + 2].medianMs / m, t[4 * p + 3].medianMs, t[4 * p + 3].medianMs / m, t[4 * p].cpuMs,
                  t[4 * p + 1].cpuMs, uniforms, states, draws);
    }
    std::fflush(stdout);
  }
  return 0;
}
