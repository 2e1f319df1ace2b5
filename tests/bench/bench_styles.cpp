// The seeds' styles, measured (issue 19). Headless at 1280x720 (by default):
//   lines   hardware outlines (fatten, edges, offset) against the object-space silhouettes on
//           the bunny, the teapot and the 871K torus: the share of each line image within a
//           pixel of the other, line widths across the silhouette (median, 10th and 90th
//           percentile), and frame costs interleaved in one run with the camera orbiting
//           (object-space silhouettes are recomputed every frame, as while a user orbits).
//   styles  every shipped style (palettes/styles) on the bunny, the teapot and the torus:
//           frame time against the `reference` path in one run, each style with its own
//           renderer and palette; the technical style also without its line sets (its lines in
//           one style) and without lines, to price the sets.
//   strokes painterly brush strokes over the smooth path against `reference` (the 871K torus
//           with a budget of 200K strokes), and their temporal stability: pixels popping between
//           frames of a slow orbit and of a zoom out, faded against cut at their rank.
//   intersections  intersection lines: the search (once per pose) on each mesh alone and on two
//           copies of it crossing, and the frame of the two copies with the technical style's
//           lines against the same with intersection lines, the camera orbiting (drawn, not
//           searched) and the second copy moving (searched every frame).
// Run: build/tests/bench/bench_styles [--size WxH] [--frames N] [--part lines|styles|strokes|intersections] [--mesh bunny|teapot|torus]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app/benchmark/interleaved_timing.h"
#include "app/settings/style_file.h"
#include "app/viewer_state.h"
#include "bench_common.h"
#include "renderer/core/heap_policy.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/lines/intersection_lines.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/renderer.h"
#include "support/line_comparison.h"

using namespace npr;

namespace {

struct BenchScene {
  const char* name;
  const Mesh* mesh;
};

const glm::vec3 kLight{2.0f, 2.5f, 3.0f};

void setLight(Renderer& r, const CameraMatrices& m) {
  r.lighting().setModelView(m.view);
  const float pos[4] = {kLight.x, kLight.y, kLight.z, 1.0f};
  (void)r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos);
}

ImageRGBA8 frame(Renderer& r, const OffscreenTarget& target, const CameraMatrices& cam, const RenderSettings& s) {
  target.bind();
  setLight(r, cam);
  if (Status st = r.render(cam, s, {0, 0, target.width(), target.height()}); !st) std::fprintf(stderr, "bench_styles: %s\n", st.error().c_str());
  return target.readRGBA8();
}

// One white entry on a white ground: only the lines are ink.
Palette whitePalette() {
  Palette p;
  p.name = "white";
  PaletteEntry e;
  e.image = ImageRGBA8{4, 4, std::vector<std::uint8_t>(64, 255)};
  e.average = glm::vec3(1.0f);
  e.intensity = 3.0f;
  p.entries.push_back(std::move(e));
  return p;
}

int lines(const std::vector<BenchScene>& scenes, const OffscreenTarget& target, int frames, const Palette& crosshatch) {
  auto created = Renderer::create();
  if (!created) return 1;
  Renderer& r = **created;
  applyDefaultMaterial(r.lighting());
  const float aspect = float(target.width()) / float(target.height());
  struct Row {
    const char* label;
    LineSettings lines;
  };
  std::vector<Row> rows = {{"no lines", {}}, {"object-space silhouettes", {}}};
  rows[1].lines.silhouettes = true;
  for (OutlineMethod m : {OutlineMethod::Fatten, OutlineMethod::Edges, OutlineMethod::Offset}) {
    Row row{nullptr, {}};
    row.lines.hardware = true;
    row.lines.outline = m;
    row.label = m == OutlineMethod::Fatten ? "hardware fatten" : m == OutlineMethod::Edges ? "hardware edges" : "hardware offset";
    rows.push_back(row);
  }
  for (Row& row : rows) row.lines.width = 3.0f;

  std::printf("## Hardware outlines against object-space silhouettes (3 px lines)\n\n");
  std::printf("| mesh | method | object-space px near it | its px near object-space | width median | p10 | p90 |\n|---|---|---|---|---|---|---|\n");
  for (const BenchScene& sc : scenes) {
    r.scene().setOnly(sc.mesh);
    if (!r.palettes().setMain(whitePalette())) return 1;
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    const CameraMatrices m = cam.matrices(aspect);
    RenderSettings s;
    s.lines = rows[1].lines;
    const test::LineMask object = test::lineMask(frame(r, target, m, s));
    const std::vector<FeatureLine> edges = r.featureLines(m, s);
    const test::Spread ow = test::spreadOf(test::widthsAcross(object, edges, m));
    std::printf("| %s | object-space | - | - | %.1f | %.1f | %.1f |\n", sc.name, double(ow.median), double(ow.p10), double(ow.p90));
    for (std::size_t i = 2; i < rows.size(); ++i) {
      s.lines = rows[i].lines;
      const test::LineMask hw = test::lineMask(frame(r, target, m, s));
      const test::Spread w = test::spreadOf(test::widthsAcross(hw, edges, m));
      std::printf("| %s | %s | %.3f | %.3f | %.1f | %.1f | %.1f |\n", sc.name, rows[i].label + 9, test::nearShare(object, hw, 1),
                  test::nearShare(hw, object, 1), double(w.median), double(w.p10), double(w.p90));
    }
    std::fflush(stdout);
  }

  std::printf("\n## Frame cost, crosshatch, pixel path, camera orbiting 0.5 degrees per frame\n\n");
  std::printf("| mesh | lines | median ms | p95 ms | CPU ms | x no lines | x object-space |\n|---|---|---|---|---|---|---|\n");
  for (const BenchScene& sc : scenes) {
    r.scene().setOnly(sc.mesh);
    if (!r.palettes().setMain(crosshatch)) return 1;
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    int failed = 0;
    const std::vector<FrameTiming> t = timeInterleaved(r, target, rows.size(), frames, 2, [&](std::size_t c, int round) {
      OrbitCamera moving = cam;
      moving.orbit(0.5f * float(round), 0.0f);
      TimedFrame f{moving.matrices(aspect), RenderSettings{}};
      f.settings.lines = rows[c].lines;
      setLight(r, f.camera);
      return f;
    }, failed);
    if (failed) return 1;
    for (std::size_t i = 0; i < rows.size(); ++i)
      std::printf("| %s | %s | %.1f | %.1f | %.1f | %.2f | %.2f |\n", sc.name, rows[i].label, t[i].medianMs, t[i].p95Ms, t[i].cpuMs,
                  t[i].medianMs / t[0].medianMs, t[i].medianMs / t[1].medianMs);
    std::fflush(stdout);
  }
  return 0;
}

int styles(const std::vector<BenchScene>& scenes, const OffscreenTarget& target, int frames) {
  struct Entry {
    std::string name;
    ViewerState state;
    std::unique_ptr<Renderer> renderer;
  };
  std::vector<Entry> entries;
  // The floor: the reference path (per-pixel Phong, no palette) with the default look.
  std::vector<std::string> files{""};
  for (const std::string& f : discoverStyles()) files.push_back(f);
  // The technical style's line sets priced: the same style with its lines in one style
  // (silhouettes and creases, hidden lines dashed) and with no lines.
  const std::string technical = *findStyle("technical");
  files.push_back(technical);
  files.push_back(technical);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string& file = files[i];
    Entry e;
    auto created = Renderer::create();
    if (!created) return 1;
    e.renderer = std::move(*created);
    applyDefaultMaterial(e.renderer->lighting());
    if (file.empty()) {
      e.name = "reference (floor)";
      e.state.settings.path = RenderPath::Reference;
    } else {
      Result<Style> st = loadStyle(file);
      if (!st) {
        std::fprintf(stderr, "bench_styles: %s\n", st.error().c_str());
        return 1;
      }
      if (Status ok = applyStyle(*st, e.state, *e.renderer); !ok) {
        std::fprintf(stderr, "bench_styles: %s\n", ok.error().c_str());
        return 1;
      }
      e.name = st->name;
      if (i + 2 >= files.size()) {  // the two variants of the technical style
        LineSettings& l = e.state.settings.lines;
        l.sets.clear();
        l.hidden = i + 2 == files.size();
        if (!l.hidden) l.silhouettes = l.creases = false;
        e.name += l.hidden ? ", lines in one style (no sets)" : ", no lines";
      }
    }
    entries.push_back(std::move(e));
  }
  const float aspect = float(target.width()) / float(target.height());
  std::printf("\n## Styles: frame time against the reference path, camera orbiting 0.5 degrees per frame\n\n");
  std::printf("| mesh | style | median ms | p95 ms | CPU ms | x reference |\n|---|---|---|---|---|---|\n");
  for (const BenchScene& sc : scenes) {
    for (Entry& e : entries) e.renderer->scene().setOnly(sc.mesh);
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    int failed = 0;
    const std::vector<FrameTiming> t = timeInterleaved(*entries[0].renderer, target, entries.size(), frames, 2, [&](std::size_t c, int round) {
      OrbitCamera moving = cam;
      moving.orbit(0.5f * float(round), 0.0f);
      TimedFrame f{moving.matrices(aspect), entries[c].state.settings, entries[c].renderer.get()};
      setLight(*entries[c].renderer, f.camera);
      return f;
    }, failed);
    if (failed) {
      std::fprintf(stderr, "bench_styles: %d frame(s) failed\n", failed);
      return 1;
    }
    for (std::size_t i = 0; i < entries.size(); ++i)
      std::printf("| %s | %s | %.1f | %.1f | %.1f | %.2f |\n", sc.name, entries[i].name.c_str(), t[i].medianMs, t[i].p95Ms, t[i].cpuMs,
                  t[i].medianMs / t[0].medianMs);
    std::fflush(stdout);
  }
  return 0;
}

// Share of the pixels covered in either frame whose luminance changed by more than 0.08
// between two consecutive frames: what a viewer sees as popping.
double changedShare(const ImageRGBA8& a, const ImageRGBA8& b, const glm::vec3& ground) {
  int covered = 0, changed = 0;
  auto lum = [](const std::uint8_t* p) { return (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f; };
  const float groundLum = 0.2126f * ground.r + 0.7152f * ground.g + 0.0722f * ground.b;
  for (std::size_t i = 0; i < a.pixels.size(); i += 4) {
    const float la = lum(&a.pixels[i]), lb = lum(&b.pixels[i]);
    if (std::abs(la - groundLum) < 0.01f && std::abs(lb - groundLum) < 0.01f) continue;
    ++covered;
    changed += std::abs(la - lb) > 0.08f;
  }
  return covered ? double(changed) / covered : 0.0;
}

int strokes(const std::vector<BenchScene>& scenes, const OffscreenTarget& target, int frames) {
  auto created = Renderer::create();
  if (!created) return 1;
  Renderer& r = **created;
  applyDefaultMaterial(r.lighting());
  Result<Palette> wood = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/wood/wood.palette");
  if (!wood || !r.palettes().setMain(*wood)) return 1;
  const float aspect = float(target.width()) / float(target.height());
  struct Row {
    std::string label;
    RenderSettings settings;
  };
  std::printf("\n## Painterly strokes: frame time against the reference path, camera orbiting 0.5 degrees per frame\n\n");
  std::printf("| mesh | row | strokes | seeding ms | median ms | p95 ms | CPU ms | x reference |\n|---|---|---|---|---|---|---|---|\n");
  for (const BenchScene& sc : scenes) {
    r.scene().setOnly(sc.mesh);
    const bool large = sc.mesh->triangleCount() > 500000;
    std::vector<Row> rows(3);
    rows[0].label = "reference";
    rows[0].settings.path = RenderPath::Reference;
    rows[1].label = "smooth (underpainting)";
    rows[1].settings.path = RenderPath::Smooth;
    rows[2].label = large ? "smooth + strokes (budget 200K)" : "smooth + strokes";
    rows[2].settings = rows[1].settings;
    rows[2].settings.strokes.on = true;
    rows[2].settings.strokes.density = large ? 1e6f : 1500.0f;
    rows[2].settings.strokes.budget = 200000;
    rows[2].settings.strokes.length = 26.0f;
    rows[2].settings.strokes.width = 9.0f;
    for (Row& row : rows) row.settings.match = MatchMode::Colors;
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    // Seeds (and the direction field) before timing: a one-off per mesh.
    frame(r, target, cam.matrices(aspect), rows[2].settings);
    const std::size_t count = r.scene().strokeCount();
    const double seedMs = r.scene().strokeSeedMs();
    int failed = 0;
    const std::vector<FrameTiming> t = timeInterleaved(r, target, rows.size(), frames, 2, [&](std::size_t c, int round) {
      OrbitCamera moving = cam;
      moving.orbit(0.5f * float(round), 0.0f);
      TimedFrame f{moving.matrices(aspect), rows[c].settings};
      setLight(r, f.camera);
      return f;
    }, failed);
    if (failed) return 1;
    for (std::size_t i = 0; i < rows.size(); ++i)
      std::printf("| %s | %s | %s | %s | %.1f | %.1f | %.1f | %.2f |\n", sc.name, rows[i].label.c_str(), i == 2 ? std::to_string(count).c_str() : "-",
                  i == 2 ? std::to_string(int(seedMs)).c_str() : "-", t[i].medianMs, t[i].p95Ms, t[i].cpuMs, t[i].medianMs / t[0].medianMs);
    std::fflush(stdout);
  }

  // Temporal stability: consecutive frames of a slow orbit and of a zoom out, pixels whose
  // luminance changes by more than 0.08 (about a stroke's step from its neighbours) as a share
  // of the covered ones. Strokes moving with the surface change pixels too; the underpainting
  // alone is the yardstick, and strokes cut at their rank instead of faded show the popping.
  std::printf("\n## Painterly strokes: pixels popping between consecutive frames (luminance change > 0.08)\n\n");
  std::printf("| mesh | motion | smooth | + strokes (faded) | + strokes (cut) |\n|---|---|---|---|---|\n");
  for (const BenchScene& sc : scenes) {
    if (sc.mesh->triangleCount() > 500000) continue;  // the bunny and the teapot say it
    r.scene().setOnly(sc.mesh);
    RenderSettings base;
    base.path = RenderPath::Smooth;
    base.match = MatchMode::Colors;
    RenderSettings faded = base, cut = base;
    faded.strokes.on = cut.strokes.on = true;
    faded.strokes.density = cut.strokes.density = 1500.0f;
    faded.strokes.length = cut.strokes.length = 26.0f;
    faded.strokes.width = cut.strokes.width = 9.0f;
    cut.tuning.strokeFade = false;
    for (const char* motion : {"orbit 0.25 deg/frame", "zoom out 1%/frame"}) {
      double sums[3] = {0, 0, 0};
      const RenderSettings* settings[3] = {&base, &faded, &cut};
      for (int k = 0; k < 3; ++k) {
        OrbitCamera cam(30.0f, 20.0f, 3.0f);
        cam.frame(sc.mesh->radius);
        ImageRGBA8 previous;
        for (int f = 0; f <= 20; ++f) {
          OrbitCamera moving = cam;
          if (motion[0] == 'o') moving.orbit(0.25f * float(f), 0.0f);
          else moving.setYawPitchDistance(30.0f, 20.0f, cam.distance() * std::pow(1.01f, float(f)) * 1.5f);
          const ImageRGBA8 img = frame(r, target, moving.matrices(aspect), *settings[k]);
          if (f > 0) sums[k] += changedShare(previous, img, wood->backgroundColour);
          previous = img;
        }
      }
      std::printf("| %s | %s | %.4f | %.4f | %.4f |\n", sc.name, motion, sums[0] / 20, sums[1] / 20, sums[2] / 20);
      std::fflush(stdout);
    }
  }
  return 0;
}

int intersections(const std::vector<BenchScene>& scenes, const OffscreenTarget& target, int frames) {
  std::printf("\n## Intersection lines: the search, once per pose (median of %d)\n\n", frames);
  std::printf("| scene | triangles | pairs tested | segments | search ms |\n|---|---|---|---|---|\n");
  // The second copy stands beside the first, overlapping a third of it.
  auto beside = [](const Mesh& m, float shift) { return glm::translate(glm::mat4(1.0f), glm::vec3(0.66f * m.radius + shift, 0.1f * m.radius, 0.0f)); };
  for (const BenchScene& sc : scenes)
    for (const bool two : {false, true}) {
      std::vector<IntersectionObject> objects = {{sc.mesh, glm::mat4(1.0f)}};
      if (two) objects.push_back({sc.mesh, beside(*sc.mesh, 0.0f)});
      std::vector<double> ms;
      IntersectionCounts counts;
      for (int i = 0; i < frames; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        (void)intersectionLines(objects, &counts);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      }
      std::printf("| %s%s | %zu | %zu | %zu | %.1f |\n", sc.name, two ? " x2, crossing" : "", counts.triangles, counts.pairsTested, counts.segments, median(ms));
      std::fflush(stdout);
    }
  std::printf("\n## Intersection lines: frames of two crossing copies, technical style's lines (silhouettes, creases, hidden lines), interleaved\n\n");
  std::printf("| scene | row | median ms | p95 ms | CPU ms | x without |\n|---|---|---|---|---|---|\n");
  const float aspect = float(target.width()) / float(target.height());
  for (const BenchScene& sc : scenes) {
    // Two renderers: the copies still (rows 0, 1) and the second copy moving (rows 2, 3).
    std::unique_ptr<Renderer> still, moving;
    ModelId movingCopy = 0;
    for (auto* r : {&still, &moving}) {
      auto created = Renderer::create();
      if (!created) return 1;
      *r = std::move(*created);
      applyDefaultMaterial((*r)->lighting());
      if (!(*r)->palettes().setMain(whitePalette())) return 1;
      (*r)->scene().setOnly(sc.mesh);
      const ModelId id = (*r)->scene().add(*sc.mesh, beside(*sc.mesh, 0.0f));
      if (r == &moving) movingCopy = id;
    }
    RenderSettings without;
    without.lines.silhouettes = without.lines.creases = without.lines.hidden = true;
    RenderSettings with = without;
    with.lines.intersections = true;
    const char* labels[4] = {"orbiting, without", "orbiting, with intersections", "copy moving, without", "copy moving, with intersections"};
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(1.7f * sc.mesh->radius);
    int failed = 0;
    const std::vector<FrameTiming> t = timeInterleaved(*still, target, 4, frames, 2, [&](std::size_t c, int round) {
      OrbitCamera turned = cam;
      turned.orbit(0.5f * float(round), 0.0f);
      Renderer* r = c < 2 ? still.get() : moving.get();
      if (c >= 2) (void)r->scene().setTransform(movingCopy, beside(*sc.mesh, 0.002f * sc.mesh->radius * float(round)));
      TimedFrame f{c < 2 ? turned.matrices(aspect) : cam.matrices(aspect), c % 2 ? with : without, r};
      setLight(*r, f.camera);
      return f;
    }, failed);
    if (failed) {
      std::fprintf(stderr, "bench_styles: %d frame(s) failed\n", failed);
      return 1;
    }
    for (std::size_t i = 0; i < 4; ++i)
      std::printf("| %s | %s | %.1f | %.1f | %.1f | %.2f |\n", sc.name, labels[i], t[i].medianMs, t[i].p95Ms, t[i].cpuMs,
                  t[i].medianMs / t[i - i % 2].medianMs);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  npr::keepFreedHeapMemory();  // frame times without the heap trimmed every frame (heap_policy.h)
  int w = 1280, h = 720, frames = 9;
  std::string part, meshFilter;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &w, &h);
    else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--part") && i + 1 < argc) part = argv[++i];
    else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc) meshFilter = argv[++i];
    else {
      std::fprintf(stderr, "usage: bench_styles [--size WxH] [--frames N] [--part lines|styles|strokes|intersections] [--mesh bunny|teapot|torus]\n");
      return 2;
    }
  }
  if (frames < 1 || w < 1 || h < 1 || (!part.empty() && part != "lines" && part != "styles" && part != "strokes" && part != "intersections") ||
      (!meshFilter.empty() && meshFilter != "bunny" && meshFilter != "teapot" && meshFilter != "torus")) {
    std::fprintf(stderr, "bench_styles: --frames and --size must be positive, --part lines, styles, strokes or intersections, --mesh bunny, teapot or torus\n");
    return 2;
  }
  auto ctx = HeadlessContext::create(false);
  if (!ctx) {
    std::fprintf(stderr, "%s\n", ctx.error().c_str());
    return 1;
  }
  auto target = OffscreenTarget::create(w, h);
  auto bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  auto teapot = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/teapot.obj");
  auto crosshatch = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/crosshatch/crosshatch.palette");
  if (!target || !bunny || !teapot || !crosshatch) {
    std::fprintf(stderr, "bench_styles: could not set up (target, models or palette)\n");
    return 1;
  }
  std::vector<BenchScene> scenes;
  if (meshFilter.empty() || meshFilter == "bunny") scenes.push_back({"bunny", &*bunny});
  if (meshFilter.empty() || meshFilter == "teapot") scenes.push_back({"teapot", &*teapot});
  if (meshFilter.empty() || meshFilter == "torus") scenes.push_back({"torus 871K", &bench::largeMesh()});
  std::printf("GL: %s; %dx%d, %d frames per row\n\n", (*ctx)->description().c_str(), w, h, frames);
  if ((part.empty() || part == "lines") && lines(scenes, *target, frames, *crosshatch)) return 1;
  if ((part.empty() || part == "styles") && styles(scenes, *target, frames)) return 1;
  if ((part.empty() || part == "strokes") && strokes(scenes, *target, frames)) return 1;
  if ((part.empty() || part == "intersections") && intersections(scenes, *target, frames)) return 1;
  return 0;
}
