// Frame time per render path, headless at 1280x720 (by default), for the bunny and the
// generated 871K-triangle torus, with palettes of 1, 10, 30, 64 and 256 entries. Reported as
// ratios to two floors measured in the same run: `reference` (per-pixel Phong, same
// lighting) and `lit-textured` (the same lighting plus one screen-space fetch: the least any
// palette path can do). The light moves every frame, so per-triangle paths pay their CPU
// work each frame, as they do while a user drags the light.
// Run: build/tests/bench/bench_frames [--size WxH] [--frames N] [--quick]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "bench_common.h"
#include "app/viewer_state.h"
#include "renderer/headless_context.h"
#include "renderer/mesh_loader.h"
#include "renderer/offscreen_target.h"
#include "renderer/renderer.h"

using namespace npr;

namespace {

// A palette of n entries cycling through the crosshatch images (timing depends on the
// number and size of entries, not on what they show).
Palette paletteOf(const Palette& base, int n) {
  Palette p;
  p.name = std::to_string(n) + " entries";
  p.backgroundColour = base.backgroundColour;
  p.backgroundImage = base.backgroundImage;
  const int m = static_cast<int>(base.entries.size());
  for (int i = 0; i < n; ++i) {
    PaletteEntry e = base.entries[static_cast<size_t>(n == 1 ? m / 2 : i * (m - 1) / std::max(1, n - 1))];
    // Spread the intensities evenly so every entry is reachable.
    e.intensity = 3.0f * (1.0f - float(i) / float(std::max(1, n - 1)));
    e.average = glm::vec3(e.intensity / 3.0f);
    p.entries.push_back(std::move(e));
  }
  return p;
}

struct Timing {
  double medianMs = 0, p95Ms = 0, cpuMs = 0, gpuMs = 0;
};

Timing timeFrames(Renderer& r, OffscreenTarget& target, const RenderSettings& s, const OrbitCamera& camera, int frames) {
  const float aspect = float(target.width()) / float(target.height());
  std::vector<double> wall, cpu, gpu;
  for (int f = -2; f < frames; ++f) {  // two warm-up frames compile and upload
    const CameraMatrices cam = camera.matrices(aspect);
    // Move the light a little every frame: per-triangle work is redone, as while dragging it.
    const float angle = 0.6f + 0.01f * float(f);
    const float pos[4] = {2.0f * std::cos(angle), 2.5f, 3.0f * std::sin(angle) + 1.0f, 1.0f};
    r.lighting().setModelView(cam.view);
    (void)r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos);
    target.bind();
    const auto t0 = std::chrono::steady_clock::now();
    (void)r.render(cam, s, {0, 0, target.width(), target.height()});
    finishGpuWork();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (f < 0) continue;
    wall.push_back(ms);
    cpu.push_back(r.stats().cpuFrameMs);
    if (r.stats().gpuMs >= 0) gpu.push_back(r.stats().gpuMs);
  }
  auto median = [](std::vector<double> v) {
    if (v.empty()) return -1.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::vector<double> sorted = wall;
  std::sort(sorted.begin(), sorted.end());
  return {median(wall), sorted[std::min(sorted.size() - 1, size_t(double(sorted.size()) * 0.95))], median(cpu), median(gpu)};
}

}  // namespace

int main(int argc, char** argv) {
  int w = 1280, h = 720, frames = 15;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &w, &h);
    else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick")) quick = true;
  }
  auto ctx = HeadlessContext::create(false);
  if (!ctx) {
    std::fprintf(stderr, "%s\n", ctx.error().c_str());
    return 1;
  }
  auto target = OffscreenTarget::create(w, h);
  auto renderer = Renderer::create();
  if (!target || !renderer) return 1;
  Renderer& r = **renderer;
  applyDefaultMaterial(r.lighting());
  auto crosshatch = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/crosshatch/crosshatch.palette");
  auto bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  if (!crosshatch || !bunny) return 1;
  struct Scene { const char* name; const Mesh* mesh; };
  std::vector<Scene> scenes = {{"bunny", &*bunny}};
  if (!quick) scenes.push_back({"torus 871K", &bench::largeMesh()});
  const std::vector<int> sizes = quick ? std::vector<int>{10} : std::vector<int>{1, 10, 30, 64, 256};
  struct PathRow { const char* label; RenderPath path; bool naive; };
  const std::vector<PathRow> paths = {{"reference", RenderPath::Reference, false}, {"lit-textured", RenderPath::LitTextured, false},
                                      {"stencil", RenderPath::Stencil, false},     {"stencil-naive", RenderPath::Stencil, true},
                                      {"triangle", RenderPath::Triangle, false},   {"vertex", RenderPath::Vertex, false},
                                      {"pixel", RenderPath::Pixel, false},         {"smooth", RenderPath::Smooth, false}};
  std::printf("GL: %s; %dx%d, %d frames per row, light moving every frame\n\n", (*ctx)->description().c_str(), w, h, frames);
  std::printf("| mesh | entries | path | median ms | p95 ms | CPU ms | GPU ms | x reference | x lit-textured |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Scene& sc : scenes) {
    r.setMesh(sc.mesh);
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    for (int n : sizes) {
      if (!r.setPalette(paletteOf(*crosshatch, n))) return 1;
      std::map<std::string, double> floor;
      for (const PathRow& p : paths) {
        RenderSettings s;
        s.path = p.path;
        s.match = MatchMode::Intensity;
        s.stencilScissor = s.stencilSkipEmpty = !p.naive;
        const Timing t = timeFrames(r, *target, s, cam, frames);
        floor[p.label] = t.medianMs;
        std::printf("| %s | %d | %s | %.1f | %.1f | %.1f | %s | %.2f | %.2f |\n", sc.name, n, p.label, t.medianMs, t.p95Ms, t.cpuMs,
                    t.gpuMs >= 0 ? std::to_string(t.gpuMs).substr(0, 5).c_str() : "n/a", t.medianMs / floor["reference"],
                    t.medianMs / floor["lit-textured"]);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
