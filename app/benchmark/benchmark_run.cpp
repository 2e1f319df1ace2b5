// The speed/accuracy benchmark (see benchmark_run.h).
//
// [SECTION] Accuracy: the independent per-pixel reference and each path's error
// [SECTION] Speed
// [SECTION] Driver
// The results' types are in benchmark_results.h, their files in benchmark_report.cpp.
#include "app/benchmark/benchmark_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "app/benchmark/benchmark_results.h"
#include "app/benchmark/interleaved_timing.h"
#include "app/benchmark/ray_reference.h"
#include "app/progress_line.h"
#include "app/headless/headless_session.h"
#include "app/viewer_state.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/gl/headless_context.h"
#include "renderer/lighting/lighting_model.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/core/parallel.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/shadows/occlusion_bake.h"
#include "app/cli.h"
#include "renderer/settings/choice_names.h"
#include "renderer/lighting/occlusion_factor.h"

namespace npr {
namespace fs = std::filesystem;

namespace {

// The scripted motion: a quarter orbit of the light and a sixth of the camera over the run.
struct MotionFrame {
  CameraMatrices camera;
  glm::vec3 light;
};
MotionFrame motion(float frame, int frames, const OrbitCamera& base, float aspect) {
  const float t = frames > 1 ? frame / float(frames - 1) : 0.0f;
  OrbitCamera cam = base;
  cam.orbit(60.0f * t, 0.0f);
  const float a = 0.4f + 1.57f * t;
  return {cam.matrices(aspect), glm::vec3(2.5f * std::cos(a), 2.0f, 2.5f * std::sin(a))};
}

Status setLight(Renderer& r, const MotionFrame& m) {
  const float pos[4] = {m.light.x, m.light.y, m.light.z, 1.0f};
  r.lighting().setModelView(m.camera.view);
  return r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos);
}

// Benchmark runs go on past a failed call, but the run then fails and says why.
void expectOk(const Status& s, std::vector<std::string>& failures) {
  if (!s) failures.push_back(s.error());
}

// ---------------------------------------------------------------------------------------
// [SECTION] Accuracy

// The paths measured for accuracy: every palette path a user can pick (from the path table).
// The others (the reference and the internal floor) are timed only.
bool measuredForAccuracy(const PathInfo& p) { return p.userSelectable && p.usesPalette; }

bool finite3(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

void measureAccuracy(Renderer& r, const Mesh& mesh, const OrbitCamera& base, glm::ivec2 size, int frames, const RenderSettings& settings,
                     ConfigResult& out) {
  // With shadows or occlusion on, the reference casts rays through the mesh for them.
  const std::optional<RayScene> rays = settings.shadows || settings.occlusion ? std::optional<RayScene>(std::in_place, mesh) : std::nullopt;
  const std::vector<glm::vec3> skyDirections = OcclusionBake::sampleDirections(OcclusionBake::kDefaultDirections);
  auto target = OffscreenTarget::create(size.x, size.y, OffscreenTarget::Format::RGBA32F);
  if (!target) return;
  const float aspect = float(size.x) / float(size.y);
  const size_t n = size_t(size.x) * size_t(size.y);
  // Per path, the previous frame's drawn tone and the ideal tone, for temporal stability.
  std::vector<std::vector<float>> prevDrawn(out.paths.size(), std::vector<float>(n, NAN));
  std::vector<float> prevIdeal(n, NAN), ideal(n, NAN);
  std::vector<int> idealIndex(n, -1);
  std::vector<glm::dvec3> idealColour(n), prevIdealColour(n);
  for (int f = 0; f < frames; ++f) {
    const MotionFrame m = motion(float(f), frames, base, aspect);
    expectOk(setLight(r, m), out.failures);
    auto geometry = [&](FrameOutput o) {
      target->clear(glm::vec4(0.0f));
      expectOk(r.render(m.camera, RenderSettings{}, {0, 0, size.x, size.y}, o == FrameOutput::EyePosition ? FrameOutput::EyePosition : FrameOutput::EyeNormal), out.failures);
      return target->readRGBA32F();
    };
    auto selection = [&](const RenderSettings& s) {
      target->clear(glm::vec4(0.0f));
      expectOk(r.render(m.camera, s, {0, 0, size.x, size.y}, FrameOutput::Blend), out.failures);
      return target->readRGBA32F();
    };
    const ImageRGBA32F pos = geometry(FrameOutput::EyePosition);
    const ImageRGBA32F nrm = geometry(FrameOutput::EyeNormal);
    // The first palette render makes the matcher for this palette, mode and scale.
    RenderSettings first = settings;
    first.path = RenderPath::Pixel;
    (void)selection(first);
    const PaletteMatcher& matcher = *r.palettes().matcher();
    const auto lighting = prepareLighting<double>(r.lighting());
    // The ideal: the lighting model in double precision at each pixel's interpolated
    // position and normal, independent of every path under test; with shadows, each light's
    // visibility by a ray toward it, and with occlusion the bake's quantity by rays in the
    // bake's directions, both from the pixel's own surface point.
    const glm::dmat4 toModel = glm::inverse(glm::dmat4(m.camera.view));
    const glm::dmat3 toModel3(toModel);
    std::vector<std::uint64_t> bad(size_t(workerCount()), 0);
    parallelChunks(n, workerCount(), [&](size_t begin, size_t end, int chunk) {
      for (size_t i = begin; i < end; ++i) {
        ideal[i] = NAN;
        idealIndex[i] = -1;
        if (nrm.pixels[i * 4 + 3] < 0.5f) continue;
        const float* p = &pos.pixels[i * 4];
        const float* q = &nrm.pixels[i * 4];
        if (!finite3(p) || !finite3(q)) {
          ++bad[size_t(chunk)];
          continue;
        }
        const glm::dvec3 pe(p[0], p[1], p[2]), ne(q[0], q[1], q[2]);
        const bool back = p[3] < 0.0f;
        glm::dvec3 scale(1.0);
        double visibility[kMaxLights];
        if (rays && glm::length(ne) > 0.0) {
          const glm::dvec3 side = glm::normalize(back && lighting.twoSided ? -ne : ne);
          const glm::dvec3 pm(toModel * glm::dvec4(pe, 1.0)), nm = toModel3 * side;
          const glm::dvec3 origin = pm + nm * rays->offset();
          for (int l = 0; settings.shadows && l < lighting.count; ++l) {
            const auto& light = lighting.lights[l];
            glm::dvec3 vp = light.position;
            double reach = INFINITY;
            if (light.positional) {
              const glm::dvec3 d = light.position - pe;
              reach = glm::length(d);
              vp = reach > 0.0 && std::isfinite(reach) ? d / reach : side;
            }
            visibility[l] = glm::dot(side, vp) > 0.0 && rays->blocked(origin, toModel3 * vp, reach) ? 0.0 : 1.0;
          }
          if (settings.occlusion) scale = glm::dvec3(occlusionFactor(rays->openness(pm, nm, skyDirections), double(settings.occlusionStrength)));
        }
        const glm::dvec3 lit = shade(lighting, pe, ne, back, scale, rays && settings.shadows ? visibility : nullptr);
        if (!std::isfinite(lit.x) || !std::isfinite(lit.y) || !std::isfinite(lit.z)) {
          ++bad[size_t(chunk)];
          continue;
        }
        idealColour[i] = lit;
        ideal[i] = settings.match == MatchMode::Colors ? 0.0f : matcher.tonePosition(glm::vec3(lit));
        idealIndex[i] = matcher.match(glm::vec3(lit));
      }
    });
    for (std::uint64_t b : bad) out.nonFinite += b;
    const auto& ranks = matcher.entryRanks();
    const auto& avg = matcher.scaledAverages();
    for (size_t k = 0; k < out.paths.size(); ++k) {
      PathResult& pr = out.paths[k];
      RenderSettings s = settings;
      s.path = pr.path;
      const ImageRGBA32F sel = selection(s);
      for (size_t i = 0; i < n; ++i) {
        const float* v = &sel.pixels[i * 4];
        if (idealIndex[i] < 0) continue;
        if (!finite3(v)) {
          ++out.nonFinite;
          continue;
        }
        const int a = std::clamp(int(std::lround(v[0])), 0, matcher.size() - 1), b = std::clamp(int(std::lround(v[1])), 0, matcher.size() - 1);
        const float t = std::clamp(v[2], 0.0f, 1.0f);
        const int nearest = t < 0.5f ? a : b;
        float drawn;  // 1D: tone in palette steps; colours: distance from the ideal colour
        if (settings.match == MatchMode::Colors) {
          const glm::dvec3 c = glm::mix(glm::dvec3(avg[size_t(a)]), glm::dvec3(avg[size_t(b)]), double(t));
          const double e = glm::length(c - glm::clamp(idealColour[i], 0.0, 1.0));
          pr.error.add(e);
          drawn = float(nearest);
        } else {
          drawn = float(ranks[size_t(a)]) + t * float(ranks[size_t(b)] - ranks[size_t(a)]);
          pr.error.add(std::fabs(double(drawn) - double(ideal[i])));
        }
        ++pr.pixels;
        pr.mismatched += nearest != idealIndex[i];
        float& prev = prevDrawn[k][i];
        if (f > 0 && !std::isnan(prev) && !std::isnan(prevIdeal[i])) {
          ++pr.compared;
          if (settings.match == MatchMode::Colors) {
            // Unordered entries: a pop is a change of entry while the ideal colour barely moved.
            if (drawn != prev && glm::length(idealColour[i] - prevIdealColour[i]) < 0.01) ++pr.pops;
          } else {
            if (std::fabs(drawn - prev) > 1.0f) ++pr.jumps;
            if (std::fabs(drawn - prev) >= 0.5f && std::fabs(ideal[i] - prevIdeal[i]) < 0.1f) ++pr.pops;
          }
        }
        prev = drawn;
      }
    }
    prevIdeal = ideal;
    prevIdealColour = idealColour;
  }
}

// ---------------------------------------------------------------------------------------
// [SECTION] Speed

// Each path's frame is a fraction of a frame further along the motion, so every per-triangle
// path redoes its CPU work instead of reusing what the path before it computed for the same
// light.
void measureSpeed(Renderer& r, const OrbitCamera& base, glm::ivec2 size, int frames, const RenderSettings& settings,
                  const std::vector<PathResult*>& paths, std::vector<std::string>& failures) {
  auto target = OffscreenTarget::create(size.x, size.y);
  if (!target) {
    failures.push_back(target.error());
    return;
  }
  const float aspect = float(size.x) / float(size.y);
  int failed = 0;
  const std::vector<FrameTiming> t = timeInterleaved(r, *target, paths.size(), frames, 2, [&](size_t p, int f) {
    RenderSettings s = settings;
    s.path = paths[p]->path;
    const MotionFrame m = motion(float(std::max(f, 0)) + float(p) / float(paths.size()), frames, base, aspect);
    expectOk(setLight(r, m), failures);
    return TimedFrame{m.camera, s};
  }, failed);
  if (failed) failures.push_back(std::to_string(failed) + " frame(s) failed to render while timing");
  for (size_t p = 0; p < paths.size(); ++p) {
    paths[p]->medianMs = t[p].medianMs;
    paths[p]->p95Ms = t[p].p95Ms;
    paths[p]->cpuMs = t[p].cpuMs;
    paths[p]->gpuMs = t[p].gpuMs;
  }
}

// Frames where nothing changes must do no lighting, uploads or shader builds.
void measureStaticFrames(Renderer& r, const OrbitCamera& base, glm::ivec2 size, const RenderSettings& settings, ConfigResult& out) {
  auto target = OffscreenTarget::create(size.x, size.y);
  if (!target) return;
  const MotionFrame m = motion(0, 1, base, float(size.x) / float(size.y));
  for (const PathInfo& p : renderPaths()) {
    if (!measuredForAccuracy(p)) continue;
    RenderSettings s = settings;
    s.path = p.id;
    for (int f = 0; f < 6; ++f) {
      expectOk(setLight(r, m), out.failures);  // re-set every frame, as the viewer does: unchanged values cost nothing
      target->bind();
      expectOk(r.render(m.camera, s, {0, 0, size.x, size.y}), out.failures);
      if (f == 0) continue;
      ++out.staticFrames;
      out.staticRecomputes += r.stats().lightingRecomputes;
      out.staticUploads += r.stats().bufferUploads;
      out.staticBuilds += r.stats().shaderBuilds;
    }
  }
}

// The same path with a minimal scene (one directional light, no specular) and a full one
// (four positional spotlights with attenuation, specular, local viewer).
void measureFeatureCost(Renderer& r, const OrbitCamera& base, glm::ivec2 size, int frames, const RenderSettings& settings,
                        ConfigResult& out) {
  LightingState saved = r.lighting();
  PathResult pr(RenderPath::Pixel, 1.0);
  LightingState& l = r.lighting();
  l = LightingState();
  const float black[4] = {0, 0, 0, 1};
  expectOk(l.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black), out.failures);
  measureSpeed(r, base, size, frames, settings, {&pr}, out.failures);
  out.lightMinimalMs = pr.medianMs;
  applyDefaultMaterial(l);
  expectOk(l.LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1), out.failures);
  for (int i = 1; i < 4; ++i) {
    const float c[4] = {0.3f, 0.3f, 0.3f, 1}, p[4] = {float(i) - 2.0f, 2.0f, 2.0f, 1.0f}, d[3] = {0, -1, -1};
    expectOk(l.Enable(GL_LIGHT0 + GLenum(i)), out.failures);
    expectOk(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_DIFFUSE, c), out.failures);
    expectOk(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_SPECULAR, c), out.failures);
    expectOk(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_POSITION, p), out.failures);
    expectOk(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_SPOT_DIRECTION, d), out.failures);
    expectOk(l.Lightf(GL_LIGHT0 + GLenum(i), GL_SPOT_CUTOFF, 60.0f), out.failures);
    expectOk(l.Lightf(GL_LIGHT0 + GLenum(i), GL_QUADRATIC_ATTENUATION, 0.05f), out.failures);
  }
  measureSpeed(r, base, size, frames, settings, {&pr}, out.failures);
  out.lightFullMs = pr.medianMs;
  r.lighting() = saved;
}

// One model, palette and match mode: accuracy of every palette path, then the speed of all
// paths, the static-frame counters and the cost of lighting features.
ConfigResult measureConfiguration(Renderer& r, const Mesh& mesh, const Palette& palette, MatchMode mode, const Options& o) {
  const int frames = o.frames > 0 ? o.frames : 120;
  OrbitCamera camera(30.0f, 20.0f, 3.0f);
  camera.frame(mesh.radius);
  r.lighting() = LightingState();
  applyDefaultMaterial(r.lighting());
  // The command line's settings over the defaults; the palette's range scale unless one is given.
  RenderSettings settings = o.look().render;
  settings.match = mode;
  if (!o.setting("range-scale")) settings.rangeScale = palette.defaultRangeScale.value_or(1.0f);
  ConfigResult c;
  c.model = fs::path(mesh.report.file).filename().string();
  // The row names the settings table gives: "+shadows", "occlusion-method=screen".
  for (const SettingValue& v : o.settings)
    if (v.row->key != "match" && v.row->key != "range-scale")
      c.model += v.row->type == SettingType::Bool ? (v.value == "on" ? " +" : " -") + v.row->key : " " + v.row->key + "=" + v.value;
  c.palette = palette.name + " (" + std::to_string(palette.entries.size()) + ")";
  c.mode = mode;
  c.errorUnit = mode == MatchMode::Colors ? "RGB distance" : "palette steps";
  const double range = mode == MatchMode::Colors ? 1.75 : double(palette.entries.size());
  for (const PathInfo& p : renderPaths())
    if (measuredForAccuracy(p)) c.paths.emplace_back(p.id, range);
  std::fprintf(stderr, "benchmark: %s, %s, match %s: accuracy...\n", c.model.c_str(), c.palette.c_str(), choiceName(mode));
  measureAccuracy(r, mesh, camera, o.size, frames, settings, c);
  for (const PathInfo& p : renderPaths())
    if (!measuredForAccuracy(p)) c.paths.emplace_back(p.id, range);
  std::fprintf(stderr, "benchmark: speed...\n");
  std::vector<PathResult*> timed;
  for (PathResult& p : c.paths) timed.push_back(&p);
  measureSpeed(r, camera, o.size, frames, settings, timed, c.failures);
  const double ref = std::find_if(c.paths.begin(), c.paths.end(), [](const PathResult& p) { return p.path == RenderPath::Reference; })->medianMs;
  for (PathResult& p : c.paths) p.xReference = ref > 0 ? p.medianMs / ref : 0.0;
  measureStaticFrames(r, camera, o.size, settings, c);
  measureFeatureCost(r, camera, o.size, std::min(frames, 30), settings, c);
  return c;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// [SECTION] Driver

int runBenchmark(const Options& o) {
  auto session = openHeadlessSession(false, o.gpu);
  if (!session) return reportFailure(session.error());
  Renderer& r = *session->renderer;
  std::error_code ec;
  fs::create_directories(o.outDir, ec);
  if (ec) return reportFailure("cannot create output folder " + o.outDir + ": " + ec.message());
  const std::vector<std::string> models = o.models.empty() ? std::vector<std::string>{defaultModelPath()} : o.models;
  const std::vector<std::string> palettes = o.palettes.empty() ? std::vector<std::string>{defaultPalettePath()} : o.palettes;
  const int frames = o.frames > 0 ? o.frames : 120;  // as measureConfiguration uses
  std::vector<ConfigResult> results;
  std::uint64_t nonFinite = 0;
  std::vector<std::string> failures;
  const int configurations = int(models.size() * palettes.size()) * (o.allMatchModes ? 3 : 1);
  ProgressLine progress("benchmark");
  int measured = 0;
  for (const std::string& modelName : models) {
    Result<Mesh> loaded = loadModel(modelName);
    if (!loaded) return reportFailure(loaded.error());
    const Mesh& mesh = *loaded;
    r.scene().setOnly(&mesh);
    for (const std::string& paletteFile : palettes) {
      auto palette = loadPalette(paletteFile);
      if (!palette) return reportFailure(palette.error());
      if (Status s = r.palettes().setMain(*palette); !s) return reportFailure(s.error());
      std::vector<MatchMode> modes = {o.setting("match") ? o.look().render.match : palette->defaultMatch.value_or(MatchMode::Intensity)};
      if (o.allMatchModes) modes = {MatchMode::Colors, MatchMode::Intensity, MatchMode::Order};
      for (const MatchMode mode : modes) {
        ConfigResult c = measureConfiguration(r, mesh, *palette, mode, o);
        nonFinite += c.nonFinite;
        for (const std::string& f : c.failures) failures.push_back(c.model + ", " + c.palette + ": " + f);
        results.push_back(std::move(c));
        progress.update(double(++measured) / configurations);
      }
    }
  }
  writeBenchmarkReport(results, o.outDir, o.size, frames, session->context->info().line());
  std::ifstream md(fs::path(o.outDir) / "results.md");
  std::printf("%s", std::string(std::istreambuf_iterator<char>(md), {}).c_str());
  if (!failures.empty()) {
    tellUser(std::to_string(failures.size()) + " call(s) failed during the benchmark; the first: " + failures.front());
    return 1;
  }
  if (nonFinite) {
    std::fprintf(stderr, "npr-viewer: %llu non-finite values seen during the benchmark\n", static_cast<unsigned long long>(nonFinite));
    return 1;
  }
  if (gl::checkErrors("end of benchmark")) return 1;
  return 0;
}

}  // namespace npr
