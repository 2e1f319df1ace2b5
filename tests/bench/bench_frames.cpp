// Frame time per render path, headless at 1280x720 (by default), for the bunny and the
// generated 871K-triangle torus, with palettes of 1, 10, 30, 64 and 256 entries. Reported as
// ratios to two floors measured in the same run: `reference` (per-pixel Phong, same
// lighting) and `lit-textured` (the same lighting plus one screen-space fetch: the least any
// palette path can do). The light moves every frame, so per-triangle paths pay their CPU
// work each frame, as they do while a user drags the light.
// Run: build/tests/bench/bench_frames [--size WxH] [--frames N] [--quick] [--mesh bunny|torus]
//      [--entries N] [--paths triangle,pixel,...] [--materials] [--patterns] [--pattern-scale S]... [--pattern-linear] [--orient] [--shadows]
//      [--static-light] [--occlusion] [--gpu-triangles] [--control] [--tone-range] [--turn-placements] [--tone-threshold]
//      [--palette-axis] [--aa]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "app/benchmark/interleaved_timing.h"
#include "bench_common.h"
#include "renderer/core/heap_policy.h"
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

struct PathRow {
  std::string label;
  RenderPath path;
  bool skipEmpty = true, scissor = true, masksFirst = true;  // the stencil path's three savings
  bool materials = false;                 // the mesh's own materials (--materials)
  bool anchored = false;                  // the anchored pattern space (--patterns)
  bool object = false;                    // the object pattern space (--patterns)
  float patternScale = 1.0f;              // texel size in pixels (--pattern-scale S)
  bool linear = false;                    // mapped lookups filtered (--pattern-linear)
  bool oriented = false;                  // strokes along the curvature (--orient)
  TurnPlacement placement = TurnPlacement::Auto;  // where the turn is applied (--turn-placements)
  bool toneThreshold = false;              // smooth: whole texels by threshold (--tone-threshold)
  bool axis = false;                      // a palette with rows, the row by depth (--palette-axis)
  bool shadows = false;                   // ground plane and shadows (--shadows)
  bool ground = false;                    // the ground plane alone (--shadows' yardstick)
  bool occlusion = false;                 // baked ambient occlusion (--occlusion)
  bool autoTone = false;                  // the automatic tone range (--tone-range)
  AntiAliasing aa = AntiAliasing::Off;    // anti-aliasing (--aa: +edges, +fxaa, +ssaa2)
  bool gpuTriangles = false;              // per-triangle lighting on the GPU (--gpu-triangles)
  bool control = false;                   // control-image palettes drawn (--control)
  bool screenOcclusion = false;           // screen-space occlusion instead of the bake (--occlusion)
};

}  // namespace

int main(int argc, char** argv) {
  npr::keepFreedHeapMemory();  // frame times without the heap trimmed every frame (heap_policy.h)
  int w = 1280, h = 720, frames = 15;
  std::vector<float> scales;  // --pattern-scale, repeatable: a row per scale
  bool patternLinear = false;  // --pattern-linear: also each mapped row filtered
  bool quick = false, materials = false, patterns = false, orient = false, shadows = false, staticLight = false, occlusion = false, gpuTriangles = false, control = false, toneRange = false, aa = false, placements = false, toneThreshold = false, paletteAxis = false;
  std::string meshFilter, pathFilter;
  std::vector<int> sizes = {1, 10, 30, 64, 256};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &w, &h);
    else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--materials")) materials = true;
    else if (!std::strcmp(argv[i], "--patterns")) patterns = true;
    else if (!std::strcmp(argv[i], "--pattern-scale") && i + 1 < argc) scales.push_back(float(std::atof(argv[++i])));
    else if (!std::strcmp(argv[i], "--pattern-linear")) patternLinear = true;
    else if (!std::strcmp(argv[i], "--orient")) orient = true;
    else if (!std::strcmp(argv[i], "--turn-placements")) orient = placements = true;
    else if (!std::strcmp(argv[i], "--tone-threshold")) toneThreshold = true;
    else if (!std::strcmp(argv[i], "--palette-axis")) paletteAxis = true;
    else if (!std::strcmp(argv[i], "--shadows")) shadows = true;
    else if (!std::strcmp(argv[i], "--static-light")) staticLight = true;
    else if (!std::strcmp(argv[i], "--occlusion")) occlusion = true;
    else if (!std::strcmp(argv[i], "--tone-range")) toneRange = true;
    else if (!std::strcmp(argv[i], "--aa")) aa = true;
    else if (!std::strcmp(argv[i], "--gpu-triangles")) gpuTriangles = true;
    else if (!std::strcmp(argv[i], "--control")) control = true;
    else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc) meshFilter = argv[++i];
    else if (!std::strcmp(argv[i], "--paths") && i + 1 < argc) pathFilter = "," + std::string(argv[++i]) + ",";
    else if (!std::strcmp(argv[i], "--entries") && i + 1 < argc) sizes = {std::atoi(argv[++i])};
    else {
      std::fprintf(stderr, "usage: bench_frames [--size WxH] [--frames N] [--quick] [--mesh bunny|torus] [--entries N] "
                           "[--paths p1,p2,...] [--materials] [--patterns] [--pattern-scale S]... [--pattern-linear] [--orient] [--turn-placements] [--tone-threshold] [--palette-axis] [--shadows] [--static-light] [--occlusion] [--gpu-triangles] [--control] [--tone-range] [--aa]\n(the reference and lit-textured floors always run; --materials draws the "
                           "torus with 16 materials, 4 textured, each path with materials off and on; --patterns adds each path with "
                           "the anchored and the object pattern space; the camera orbits 1 degree per frame; --orient uses the hatch palette and adds each "
                           "path with strokes along the curvature; --tone-threshold adds the smooth path with crisp tone (+threshold, --tone-blend threshold); --palette-axis gives the palette a second row (the same images) on a depth axis across the model and adds each path with it (+axis), the rows without drawing the first row only (--no-palette-axis); --turn-placements also each +orient row with the turn forced into the mesh pass (+in-mesh) and into the resolve pass (+resolved), the choice automatic placement makes by density; --shadows adds each GPU-lit path with the ground plane, then with its shadows too; "
                           "--static-light keeps the light still, so shadow maps are drawn once; --occlusion adds each GPU-lit path with baked "
                           "ambient occlusion, baked before timing, and each per-pixel one with screen-space occlusion (+ssao); --gpu-triangles adds the per-triangle paths lit on the GPU; --control adds each +shadows and "
                           "+occlusion row again with a control-image palette (stipple) drawn in shadows and crevices; --tone-range adds each palette path with the automatic tone range (+auto); --aa adds each palette path with the shader's tone edges (+edges) and with 2x2 supersampling (+ssaa2))\n");
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
  int failure = 0;
  const std::unique_ptr<HeadlessContext> ctx = bench::openBenchContext(failure);  // NPR_GPU, as for the viewer's --gpu
  if (!ctx) return failure;
  auto target = OffscreenTarget::create(w, h);
  auto renderer = Renderer::create();
  if (!target || !renderer) return 1;
  Renderer& r = **renderer;
  applyDefaultMaterial(r.lighting());
  // --orient: the one-direction hatch palette (every entry but blank and solid has a stroke
  // direction), so the +orient rows turn every lookup.
  auto crosshatch = loadPalette(std::string(NPR_SOURCE_DIR) + (orient ? "/palettes/hatch/hatch.palette" : "/palettes/crosshatch/crosshatch.palette"));
  auto bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  if (!crosshatch || !bunny) return 1;
  if (control) {
    auto stipple = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/stipple/stipple.palette");
    if (!stipple || !r.palettes().setControl(ControlParameter::Shadow, *stipple) || !r.palettes().setControl(ControlParameter::Occlusion, *stipple)) return 1;
  }
  struct Scene { const char* name; const Mesh* mesh; };
  std::vector<Scene> scenes;
  if (meshFilter.empty() || meshFilter == "bunny") scenes.push_back({"bunny", &*bunny});
  if (materials) scenes = {{"torus 871K, 16 materials", &bench::largeMaterialMesh()}};
  else if ((meshFilter.empty() && !quick) || meshFilter == "torus") scenes.push_back({"torus 871K", &bench::largeMesh()});
  // stencil-per-bucket draws each bucket's mask and quads in turn (surface buffers, if any, in
  // passes of their own); stencil-unbounded also draws full-screen quads, skipping only empty
  // buckets; stencil-naive does none of it (the original): each row takes one saving away.
  // From the path table: the two floors (the paths without a palette or not offered to
  // users: reference, lit-textured) first, then every palette path.
  std::vector<PathRow> allPaths;
  for (const PathInfo& p : renderPaths())
    if (!(p.userSelectable && p.usesPalette)) allPaths.push_back({p.name, p.id});
  for (const PathInfo& p : renderPaths()) {
    if (!(p.userSelectable && p.usesPalette)) continue;
    allPaths.push_back({p.name, p.id});
    if (p.id == RenderPath::Stencil) {
      allPaths.push_back({"stencil-per-bucket", RenderPath::Stencil, true, true, false});
      allPaths.push_back({"stencil-unbounded", RenderPath::Stencil, true, false, false});
      allPaths.push_back({"stencil-naive", RenderPath::Stencil, false, false, false});
    }
  }
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
    if (pathFilter.empty() || !pathInfo(p.path).userSelectable || !pathInfo(p.path).usesPalette ||
        pathFilter.find("," + p.label + ",") != std::string::npos) {
      paths.push_back(p);
      if (materials) {
        PathRow on = p;
        on.label += "+materials";
        on.materials = true;
        paths.push_back(on);
      }
      if (patterns && pathInfo(p.path).usesPalette) {
        PathRow on = p;
        on.label += "+anchored";
        on.anchored = true;
        paths.push_back(on);
        if (patternLinear) {
          on.label += "+linear";
          on.linear = true;
          paths.push_back(on);
        }
        PathRow glued = p;
        glued.label += "+object";
        glued.object = true;
        paths.push_back(glued);
      }
      for (float scale : scales)
        if (pathInfo(p.path).usesPalette) {
          PathRow on = p;
          char label[32];
          std::snprintf(label, sizeof label, "+scale%g", double(scale));
          on.label += label;
          on.patternScale = scale;
          paths.push_back(on);
          if (patternLinear) {
            on.label += "+linear";
            on.linear = true;
            paths.push_back(on);
          }
        }
      if (shadows && p.path != RenderPath::Triangle && p.path != RenderPath::Stencil) {
        PathRow on = p;
        on.label += "+ground";
        on.ground = true;
        paths.push_back(on);
        on.label += "+shadows";
        on.shadows = true;
        paths.push_back(on);
        if (control) {
          on.label += "+control";
          on.control = true;
          paths.push_back(on);
        }
      }
      if (occlusion && p.path != RenderPath::Triangle && p.path != RenderPath::Stencil) {
        PathRow on = p;
        on.label += "+occlusion";
        on.occlusion = true;
        paths.push_back(on);
        if (control) {
          on.label += "+control";
          on.control = true;
          paths.push_back(on);
        }
        if (p.path == RenderPath::Pixel || p.path == RenderPath::Smooth || p.path == RenderPath::Reference) {
          PathRow screen = p;
          screen.label += "+ssao";
          screen.occlusion = screen.screenOcclusion = true;
          paths.push_back(screen);
        }
      }
      if (toneRange && pathInfo(p.path).usesPalette) {
        PathRow on = p;
        on.label += "+auto";
        on.autoTone = true;
        paths.push_back(on);
      }
      if (aa && pathInfo(p.path).usesPalette && p.path != RenderPath::LitTextured)
        for (AntiAliasing a : {AntiAliasing::Edges, AntiAliasing::Fxaa, AntiAliasing::Ssaa2}) {
          PathRow on = p;
          on.label += a == AntiAliasing::Edges ? "+edges" : a == AntiAliasing::Fxaa ? "+fxaa" : "+ssaa2";
          on.aa = a;
          paths.push_back(on);
        }
      if (gpuTriangles && (p.path == RenderPath::Triangle || p.path == RenderPath::Stencil)) {
        PathRow on = p;
        on.label += "+gpu-lit";
        on.gpuTriangles = true;
        paths.push_back(on);
      }
      if (paletteAxis && pathInfo(p.path).usesPalette && p.path != RenderPath::LitTextured) {
        PathRow on = p;
        on.label += "+axis";
        on.axis = true;
        paths.push_back(on);
      }
      if (toneThreshold && p.path == RenderPath::Smooth) {
        PathRow on = p;
        on.label += "+threshold";
        on.toneThreshold = true;
        paths.push_back(on);
      }
      if (orient && pathInfo(p.path).usesPalette) {
        PathRow on = p;
        on.label += "+orient";
        on.oriented = true;
        paths.push_back(on);
        if (placements) {
          for (auto [where, label] : {std::pair{TurnPlacement::InMeshPass, "+in-mesh"}, std::pair{TurnPlacement::Resolved, "+resolved"}}) {
            PathRow forced = on;
            forced.label += label;
            forced.placement = where;
            paths.push_back(forced);
          }
        }
      }
    }
  std::printf("GL: %s; %dx%d, %d frames per row, light moving every frame\n\n", ctx->info().line().c_str(), w, h, frames);
  std::printf("| mesh | entries | path | median ms | p95 ms | CPU ms | CPU shading ms | GPU ms | x reference | x lit-textured |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Scene& sc : scenes) {
    r.scene().setOnly(sc.mesh);
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    for (int n : sizes) {
      Palette palette = paletteOf(*crosshatch, n);
      if (paletteAxis) {
        // A second row of the same images, the row by distance over the whole visible model
        // (the camera sits at 3 radii): every pixel between the rows, the smooth path's worst case.
        if (n > kMaxPaletteEntries / 2) {
          std::fprintf(stderr, "bench_frames: --palette-axis needs --entries %d or fewer (two rows)\n", kMaxPaletteEntries / 2);
          return 2;
        }
        const std::vector<PaletteEntry> first = palette.entries;
        palette.entries.insert(palette.entries.end(), first.begin(), first.end());
        palette.axis = PaletteAxis{PaletteAxisKind::Depth, 2.0f, 3.0f, 2};
      }
      if (!r.palettes().setMain(palette)) return 1;
      // The light moves before every frame, so each per-triangle path redoes its CPU work (as
      // while a user drags the light) rather than reusing what the path before it computed.
      CameraMatrices matrices = cam.matrices(float(w) / float(h));
      int call = 0, failed = 0;
      const std::vector<FrameTiming> t = timeInterleaved(r, *target, paths.size(), frames, 2, [&](size_t p, int) {
        RenderSettings s;
        s.path = paths[p].path;
        s.match = MatchMode::Intensity;
        s.stencilScissor = paths[p].scissor;
        s.stencilSkipEmpty = paths[p].skipEmpty;
        s.stencilMasksFirst = paths[p].masksFirst;
        s.materials = paths[p].materials;
        s.pattern = paths[p].anchored ? PatternSpace::Anchored : paths[p].object ? PatternSpace::Object : PatternSpace::Screen;
        s.patternScale = paths[p].patternScale;
        s.patternLinearFilter = paths[p].linear;
        if (paths[p].oriented) s.orient.source = OrientSource::Curvature;
        s.tuning.turnPlacement = paths[p].placement;
        s.toneBlend = paths[p].toneThreshold ? ToneBlend::Threshold : ToneBlend::Mix;
        s.paletteAxis = paths[p].axis;
        s.ground = paths[p].ground;
        s.shadows = paths[p].shadows;
        s.occlusion = paths[p].occlusion;
        s.toneRange = paths[p].autoTone ? ToneRange::Auto : ToneRange::Fixed;
        s.controlPalettes = paths[p].control;
        s.aa = paths[p].aa;
        if (paths[p].screenOcclusion) s.occlusionMethod = OcclusionMethod::Screen;
        s.triangleLighting = paths[p].gpuTriangles ? TriangleLighting::Gpu : TriangleLighting::Cpu;
        if (patterns) {  // a moving camera, so the anchored rows fit real motion
          OrbitCamera moving = cam;
          moving.orbit(0.05f * float(call), 0.0f);
          matrices = moving.matrices(float(w) / float(h));
        }
        const float angle = 0.6f + (staticLight ? 0.0f : 0.002f * float(call++));
        const float pos[4] = {2.0f * std::cos(angle), 2.5f, 3.0f * std::sin(angle) + 1.0f, 1.0f};
        r.lighting().setModelView(matrices.view);
        if (!r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos)) ++failed;
        return TimedFrame{matrices, s};
      }, failed);
      if (failed) {
        std::fprintf(stderr, "bench_frames: %d frame(s) failed\n", failed);
        return 1;
      }
      const double reference = t[0].medianMs, litTextured = t[1].medianMs;
      for (size_t p = 0; p < paths.size(); ++p) {
        std::printf("| %s | %d | %s | %.1f | %.1f | %.1f | %.1f | %s | %.2f | %.2f |\n", sc.name, n, paths[p].label.c_str(), t[p].medianMs,
                    t[p].p95Ms, t[p].cpuMs, t[p].shadingMs, t[p].gpuMs >= 0 ? std::to_string(t[p].gpuMs).substr(0, 5).c_str() : "n/a",
                    t[p].medianMs / reference, t[p].medianMs / litTextured);
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
