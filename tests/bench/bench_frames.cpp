// Frame time per render path, headless at 1280x720 (by default), for the bunny and the
// generated 871K-triangle torus, with palettes of 1, 10, 30, 64 and 256 entries. Reported as
// ratios to two floors measured in the same run: `reference` (per-pixel Phong, same
// lighting) and `lit-textured` (the same lighting plus one screen-space fetch: the least any
// palette path can do). The light moves every frame, so per-triangle paths pay their CPU
// work each frame, as they do while a user drags the light.
// Run: build/tests/bench/bench_frames [--size WxH] [--frames N] [--quick] [--mesh bunny|torus]
//      [--entries N] [--paths triangle,pixel,...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench_common.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/gl/headless_context.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/gl/offscreen_target.h"
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
  double medianMs = 0, p95Ms = 0, cpuMs = 0, shadingMs = 0, gpuMs = 0;
};

struct PathRow {
  const char* label;
  RenderPath path;
  bool skipEmpty = true, scissor = true;  // the stencil path's two savings
};

double median(std::vector<double> v) {
  if (v.empty()) return -1.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Frames of every path interleaved, one frame of each in turn: the machine's load drifts over
// seconds, and timing each path in its own block made ratios swing by 30%. The light moves
// before every frame, so each per-triangle path redoes its CPU work (as while a user drags
// the light) rather than reusing what the path before it computed.
std::vector<Timing> timeFrames(Renderer& r, OffscreenTarget& target, const std::vector<PathRow>& paths,
                               const OrbitCamera& camera, int frames) {
  const float aspect = float(target.width()) / float(target.height());
  const CameraMatrices cam = camera.matrices(aspect);
  std::vector<std::vector<double>> wall(paths.size()), cpu(paths.size()), shading(paths.size()), gpu(paths.size());
  int call = 0;
  for (int f = -2; f < frames; ++f) {  // two warm-up rounds compile and upload
    for (size_t p = 0; p < paths.size(); ++p) {
      RenderSettings s;
      s.path = paths[p].path;
      s.match = MatchMode::Intensity;
      s.stencilScissor = paths[p].scissor;
      s.stencilSkipEmpty = paths[p].skipEmpty;
      const float angle = 0.6f + 0.002f * float(call++);
      const float pos[4] = {2.0f * std::cos(angle), 2.5f, 3.0f * std::sin(angle) + 1.0f, 1.0f};
      r.lighting().setModelView(cam.view);
      (void)r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos);
      target.bind();
      const auto t0 = std::chrono::steady_clock::now();
      (void)r.render(cam, s, {0, 0, target.width(), target.height()});
      finishGpuWork();
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      r.collectGpuTime();
      if (f < 0) continue;
      wall[p].push_back(ms);
      cpu[p].push_back(r.stats().cpuFrameMs);
      shading[p].push_back(r.stats().cpuShadingMs);
      if (r.stats().gpuMs >= 0) gpu[p].push_back(r.stats().gpuMs);
    }
  }
  std::vector<Timing> out;
  for (size_t p = 0; p < paths.size(); ++p) {
    std::vector<double> sorted = wall[p];
    std::sort(sorted.begin(), sorted.end());
    out.push_back({median(wall[p]), sorted[std::min(sorted.size() - 1, size_t(double(sorted.size()) * 0.95))], median(cpu[p]),
                   median(shading[p]), median(gpu[p])});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int w = 1280, h = 720, frames = 15;
  bool quick = false;
  std::string meshFilter, pathFilter;
  std::vector<int> sizes = {1, 10, 30, 64, 256};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &w, &h);
    else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc) meshFilter = argv[++i];
    else if (!std::strcmp(argv[i], "--paths") && i + 1 < argc) pathFilter = "," + std::string(argv[++i]) + ",";
    else if (!std::strcmp(argv[i], "--entries") && i + 1 < argc) sizes = {std::atoi(argv[++i])};
    else {
      std::fprintf(stderr, "usage: bench_frames [--size WxH] [--frames N] [--quick] [--mesh bunny|torus] [--entries N] "
                           "[--paths p1,p2,...]\n(the reference and lit-textured floors always run)\n");
      return 2;
    }
  }
  if (frames < 1 || w < 1 || h < 1 || sizes[0] < 1 || sizes[0] > 256) {
    std::fprintf(stderr, "bench_frames: --frames, --size and --entries (1..256) must be positive\n");
    return 2;
  }
  if (quick) sizes = {10};
  if (!meshFilter.empty() && meshFilter != "bunny" && meshFilter != "torus") {
    std::fprintf(stderr, "bench_frames: --mesh must be bunny or torus, not '%s'\n", meshFilter.c_str());
    return 2;
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
  std::vector<Scene> scenes;
  if (meshFilter.empty() || meshFilter == "bunny") scenes.push_back({"bunny", &*bunny});
  if ((meshFilter.empty() && !quick) || meshFilter == "torus") scenes.push_back({"torus 871K", &bench::largeMesh()});
  // stencil-unbounded skips empty buckets but draws full-screen quads; stencil-naive does
  // neither (the original): the rows between them show what each saving is worth.
  const std::vector<PathRow> allPaths = {{"reference", RenderPath::Reference},
                                         {"lit-textured", RenderPath::LitTextured},
                                         {"stencil", RenderPath::Stencil},
                                         {"stencil-unbounded", RenderPath::Stencil, true, false},
                                         {"stencil-naive", RenderPath::Stencil, false, false},
                                         {"triangle", RenderPath::Triangle},
                                         {"vertex", RenderPath::Vertex},
                                         {"pixel", RenderPath::Pixel},
                                         {"smooth", RenderPath::Smooth}};
  for (size_t at = 1; at < pathFilter.size();) {
    const size_t end = pathFilter.find(',', at);
    const std::string name = pathFilter.substr(at, end - at);
    at = end + 1;
    if (!name.empty() && std::none_of(allPaths.begin(), allPaths.end(), [&](const PathRow& p) { return name == p.label; })) {
      std::fprintf(stderr, "bench_frames: unknown path '%s' in --paths\n", name.c_str());
      return 2;
    }
  }
  std::vector<PathRow> paths;
  for (const PathRow& p : allPaths)
    if (pathFilter.empty() || p.path == RenderPath::Reference || p.path == RenderPath::LitTextured ||
        pathFilter.find("," + std::string(p.label) + ",") != std::string::npos)
      paths.push_back(p);
  std::printf("GL: %s; %dx%d, %d frames per row, light moving every frame\n\n", (*ctx)->description().c_str(), w, h, frames);
  std::printf("| mesh | entries | path | median ms | p95 ms | CPU ms | CPU shading ms | GPU ms | x reference | x lit-textured |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Scene& sc : scenes) {
    r.setMesh(sc.mesh);
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    for (int n : sizes) {
      if (!r.setPalette(paletteOf(*crosshatch, n))) return 1;
      const std::vector<Timing> t = timeFrames(r, *target, paths, cam, frames);
      const double reference = t[0].medianMs, litTextured = t[1].medianMs;
      for (size_t p = 0; p < paths.size(); ++p) {
        std::printf("| %s | %d | %s | %.1f | %.1f | %.1f | %.1f | %s | %.2f | %.2f |\n", sc.name, n, paths[p].label, t[p].medianMs,
                    t[p].p95Ms, t[p].cpuMs, t[p].shadingMs, t[p].gpuMs >= 0 ? std::to_string(t[p].gpuMs).substr(0, 5).c_str() : "n/a",
                    t[p].medianMs / reference, t[p].medianMs / litTextured);
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
