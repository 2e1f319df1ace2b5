// What the light terms cost outside the frame: the ambient occlusion bake per mesh (64
// directions, 1024^2 depth maps) and one redraw of the shadow maps per light kind, for the
// bunny and the 871K-triangle torus (median of 3); and the GPU per-triangle lighting's entries
// against the CPU's (share of triangles that differ, light from four directions). Frame-time
// ratios are bench_frames --shadows / --occlusion / --gpu-triangles.
// Run: build/tests/bench/bench_shadows [--quick]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench_common.h"
#include "renderer/core/heap_policy.h"
#include "renderer/core/elapsed.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/renderer.h"

using namespace npr;

namespace {

double medianOf(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  npr::keepFreedHeapMemory();  // frame times without the heap trimmed every frame (heap_policy.h)
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else {
      std::fprintf(stderr, "usage: bench_shadows [--quick]\n");
      return 2;
    }
  }
  auto ctx = HeadlessContext::create(false);
  if (!ctx) {
    std::fprintf(stderr, "%s\n", ctx.error().c_str());
    return 1;
  }
  auto renderer = Renderer::create();
  auto target = OffscreenTarget::create(64, 64);
  auto palette = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/crosshatch/crosshatch.palette");
  auto bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  if (!renderer || !target || !palette || !bunny || !(*renderer)->palettes().setMain(*palette)) return 1;
  Renderer& r = **renderer;
  applyDefaultMaterial(r.lighting());
  struct Scene { const char* name; const Mesh* mesh; };
  std::vector<Scene> scenes = {{"bunny", &*bunny}};
  if (!quick) scenes.push_back({"torus 871K", &bench::largeMesh()});
  OrbitCamera cam(30.0f, 20.0f, 3.0f);
  cam.frame(1.0f);
  const CameraMatrices m = cam.matrices(1.0f);
  std::printf("GL: %s\n\n| mesh | triangles | occlusion bake ms | shadow maps ms: directional | spot | point outside | point among the casters "
              "| GPU/CPU per-triangle entries differ | by more than one |\n|---|---|---|---|---|---|---|---|---|\n",
              (*ctx)->description().c_str());
  for (const Scene& sc : scenes) {
    std::vector<double> bake;
    for (int k = 0; k < 3; ++k) {
      r.scene().setOnly(sc.mesh);  // a fresh bake
      RenderSettings s;
      s.occlusion = true;
      target->bind();
      if (!r.render(m, s, {0, 0, 64, 64})) return 1;
      finishGpuWork();
      bake.push_back(r.scene().first()->occlusionBake()->ms());
    }
    // One redraw of the maps for each light kind: the light moves a little between renders.
    struct Kind { glm::vec4 position; float cutoff; };
    const Kind kinds[] = {{{1, 1, 0.5f, 0}, 180.0f}, {{2, 2, 1, 1}, 40.0f}, {{2, 2, 1, 1}, 180.0f}, {{0.1f, 0.2f, 0.1f, 1}, 180.0f}};
    std::vector<double> kindMs;
    for (const Kind& k : kinds) {
      std::vector<double> ms;
      for (int rep = 0; rep < 4; ++rep) {
        r.lighting().setModelView(m.view);
        const float pos[4] = {k.position.x + 0.01f * rep, k.position.y, k.position.z, k.position.w};
        const float dir[3] = {-k.position.x, -k.position.y, -k.position.z};
        if (!r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos) || !r.lighting().Lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, dir) ||
            !r.lighting().Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, k.cutoff))
          return 1;
        RenderSettings plain, shadowed;
        shadowed.shadows = true;
        target->bind();
        // The same frame without and with shadows: the difference is the maps' redraw (the
        // 64x64 frame itself costs little).
        const auto t0 = std::chrono::steady_clock::now();
        if (!r.render(m, plain, {0, 0, 64, 64})) return 1;
        finishGpuWork();
        const double plainMs = msSince(t0);
        const auto t1 = std::chrono::steady_clock::now();
        if (!r.render(m, shadowed, {0, 0, 64, 64})) return 1;
        finishGpuWork();
        if (rep > 0) ms.push_back(msSince(t1) - plainMs);  // the first also builds programs
      }
      kindMs.push_back(medianOf(ms));
    }
    // GPU against CPU per-triangle entries, no shadows, four light directions.
    std::size_t differ = 0, far = 0, total = 0;
    for (int k = 0; k < 4; ++k) {
      r.lighting().setModelView(m.view);
      const float pos[4] = {std::cos(1.3f * k), 1.0f, std::sin(1.3f * k), 0.0f};
      const float cutoff = 180.0f;
      if (!r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos) || !r.lighting().Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff)) return 1;
      RenderSettings cpu, gpu;
      cpu.path = gpu.path = RenderPath::Triangle;
      cpu.triangleLighting = TriangleLighting::Cpu;
      gpu.triangleLighting = TriangleLighting::Gpu;
      target->bind();
      if (!r.render(m, cpu, {0, 0, 64, 64})) return 1;
      const std::vector<std::uint8_t> a = r.scene().first()->triangles().shading().entry;
      if (!r.render(m, gpu, {0, 0, 64, 64})) return 1;
      const std::vector<std::uint8_t>& b = r.scene().first()->triangles().shading().entry;
      for (std::size_t t = 0; t < a.size() && t < b.size(); ++t) {
        differ += a[t] != b[t];
        far += std::abs(int(a[t]) - int(b[t])) > 1;
      }
      total += a.size();
    }
    std::printf("| %s | %zu | %.0f | %.1f | %.1f | %.1f | %.1f | %.3f%% | %zu |\n", sc.name, sc.mesh->triangleCount(), medianOf(bake), kindMs[0],
                kindMs[1], kindMs[2], kindMs[3], 100.0 * double(differ) / double(std::max<std::size_t>(total, 1)), far);
    std::fflush(stdout);
  }
  return 0;
}
