// A deforming mesh against the same mesh still, per path: a torus skinned to two joints and
// bent a little further every frame, and the same torus with one morph target whose weight
// changes every frame, against it static (headless, interleaved: one frame of each in turn).
// Each pose is made in the frame (Renderer::applyPoses): on the CPU and uploaded (--deform cpu),
// or on the GPU (--deform gpu; the per-triangle paths also make it on the CPU, which they read),
// the CPU's share reported beside the frame. The light stays, so a static mesh's per-triangle
// paths reuse their lighting while a deforming one's light every triangle every frame: their
// ratio is the whole per-triangle cost of animation.
// Run: build/tests/bench/bench_animation [--size WxH] [--frames N] [--quick]
#include <chrono>
#include <map>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app/benchmark/interleaved_timing.h"
#include "bench_common.h"
#include "renderer/animation/deformation.h"
#include "renderer/core/heap_policy.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/renderer.h"

using namespace npr;

namespace {

// Two joints across x: the right half turns about z around the middle.
Mesh skinned(Mesh m) {
  m.deformation.joints.assign(m.positions.size(), glm::u16vec4(0, 1, 0, 0));
  for (const glm::vec3& p : m.positions) {
    const float w = std::clamp((p.x + 0.2f) / 0.4f, 0.0f, 1.0f);
    m.deformation.weights.push_back(glm::vec4(1.0f - w, w, 0.0f, 0.0f));
  }
  return m;
}

// One target: every vertex pushed out along its normal by a tenth of the radius.
Mesh morphing(Mesh m) {
  m.deformation.targetPositions.assign(1, {});
  m.deformation.targetNormals.assign(1, std::vector<glm::vec3>(m.positions.size(), glm::vec3(0.0f)));
  for (const glm::vec3& n : m.normals) m.deformation.targetPositions[0].push_back(0.1f * n);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  npr::keepFreedHeapMemory();
  std::optional<bench::ImageBenchArgs> args = bench::parseImageBenchArgs(argc, argv, "bench_animation");
  if (!args) return 2;
  int failure = 0;
  const std::unique_ptr<HeadlessContext> ctx = bench::openBenchContext(failure);  // NPR_GPU, as for the viewer's --gpu
  if (!ctx) return failure;
  auto target = OffscreenTarget::create(args->width, args->height);
  if (!target) return 1;
  auto palette = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/crosshatch/crosshatch.palette");
  if (!palette) return 1;
  std::printf("# bench_animation: %s, %dx%d, %d frames, median ms (interleaved); the pose is made in the frame; "
              "pose: the CPU's share of it\n",
              ctx->info().line().c_str(), args->width, args->height, args->frames);
  std::printf("%-9s %-9s %8s | %8s %8s %8s %8s | %8s %8s %8s %8s\n", "vertices", "path", "static", "skin cpu", "pose", "skin gpu", "pose",
              "mrph cpu", "pose", "mrph gpu", "pose");
  std::printf("%-9s %-9s %8s | %8s %8s %8s %8s | %8s %8s %8s %8s\n", "", "", "", "x", "", "x", "", "x", "", "x", "");
  const std::vector<RenderPath> paths = {RenderPath::Stencil, RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth};
  // Tori of about 100K and 871K vertices.
  const std::vector<int> sides = args->quick ? std::vector<int>{100} : std::vector<int>{317, 933};
  // Per path: still; skinned posed on the CPU, on the GPU; morphing on the CPU, on the GPU.
  constexpr std::size_t kConfigs = 5;
  for (int side : sides) {
    const Mesh still = torus(side, side);
    const Mesh skin = skinned(still), morph = morphing(still);
    auto rs = Renderer::create(), rk = Renderer::create(), rm = Renderer::create();
    if (!rs || !rk || !rm) return 1;
    for (Renderer* r : {rs->get(), rk->get(), rm->get()}) {
      applyDefaultMaterial(r->lighting());
      if (!r->palettes().setMain(*palette)) return 1;
    }
    (*rs)->scene().add(still);
    const ModelId k = (*rk)->scene().add(skin);
    const ModelId m = (*rm)->scene().add(morph);
    OrbitCamera cam(20.0f, 25.0f, 3.0f);
    cam.frame(1.0f);
    const CameraMatrices matrices = cam.matrices(float(args->width) / float(args->height));
    std::vector<std::vector<double>> poseMs(kConfigs * paths.size());
    // The configuration each renderer drew last, whose pose time its stats hold.
    std::map<Renderer*, long> drawnLast;
    int failed = 0, call = 0, lastRound = -1;
    const std::vector<FrameTiming> t = timeInterleaved(**rs, *target, kConfigs * paths.size(), args->frames, 2,
        [&](std::size_t config, int round) {
          RenderSettings s;
          s.path = paths[config / kConfigs];
          const std::size_t kind = config % kConfigs;
          s.deform = kind == 2 || kind == 4 ? PosePlacement::Gpu : PosePlacement::Cpu;
          Renderer* r = kind == 0 ? rs->get() : kind <= 2 ? rk->get() : rm->get();
          if (auto it = drawnLast.find(r); it != drawnLast.end() && it->second >= 0 && lastRound >= 0)
            poseMs[std::size_t(it->second)].push_back(r->stats().cpuPoseMs);
          const float phase = 0.05f * float(call++);
          if (kind == 1 || kind == 2) {
            const std::vector<glm::mat4> joints = {glm::mat4(1.0f), glm::rotate(glm::mat4(1.0f), 0.5f * std::sin(phase), glm::vec3(0, 0, 1))};
            if (!r->scene().deform(k, joints, {})) ++failed;
          } else if (kind >= 3) {
            if (!r->scene().deform(m, {}, {0.5f + 0.5f * std::sin(phase)})) ++failed;
          }
          drawnLast[r] = long(config);
          lastRound = round;
          return TimedFrame{matrices, s, r};
        }, failed);
    if (failed) {
      std::fprintf(stderr, "bench_animation: %d frame(s) failed\n", failed);
      return 1;
    }
    for (std::size_t p = 0; p < paths.size(); ++p) {
      const auto at = [&](std::size_t kind) { return t[kConfigs * p + kind].medianMs; };
      const auto pose = [&](std::size_t kind) { return poseMs[kConfigs * p + kind].empty() ? 0.0 : median(poseMs[kConfigs * p + kind]); };
      const double base = at(0);
      std::printf("%-9zu %-9s %8.2f | %8.2f %8.2f %8.2f %8.2f | %8.2f %8.2f %8.2f %8.2f\n", still.positions.size(), renderPathName(paths[p]), base,
                  at(1), pose(1), at(2), pose(2), at(3), pose(3), at(4), pose(4));
      std::printf("%-9s %-9s %8s | %7.2fx %8s %7.2fx %8s | %7.2fx %8s %7.2fx %8s\n", "", "", "", at(1) / base, "", at(2) / base, "", at(3) / base, "",
                  at(4) / base, "");
    }
    std::fflush(stdout);
  }
  return 0;
}
