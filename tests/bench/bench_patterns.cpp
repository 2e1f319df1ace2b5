// What each pattern space costs and gains under motion, headless: per camera script (orbit,
// pan, zoom) and mesh (the bunny, the 871K-triangle torus),
//  - slide: how far the pattern moves relative to the surface under it, in pixels per frame,
//    over covered pixels (a surface point's screen motion minus the motion of the pattern
//    texel under it, from the geometry and the pattern's frame; independent of the shader);
//    for `anchored` also the least slide any one similarity could have each frame (the rest
//    is parallax: no 2D similarity follows it);
//  - tone: the model's mean luminance against `screen`'s at each frame, in palette steps
//    (the mean luminance difference between neighbouring entries), worst over the script;
//  - contrast: the standard deviation of luminance over the model, first and last frame;
//  - fit: the anchored frame's CPU cost per frame.
// Run: build/tests/bench/bench_patterns [--frames N] [--size WxH] [--quick]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench_common.h"
#include "support/pattern_motion.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/renderer.h"

using namespace npr;

namespace {

struct Script {
  const char* name;
  float orbit = 0.0f;           // degrees per frame
  glm::vec2 pan{0.0f};          // pixels per frame (y down)
  float zoom = 1.0f;            // magnification per frame
};

float luminance(const std::uint8_t* p) { return (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f; }

struct Run {
  double slide = 0.0;   // mean over frames of the mean over covered pixels
  double floor = 0.0;   // the same for the best similarity each frame (test::leastSimilaritySlide)
  double anisotropy = 1.0, scaleSpread = 1.0;  // flatness on screen, first frame (object space)
  std::vector<float> meanTone, contrast;
  double fitMs = 0.0;
  int samples = 0;
};

// How far from flat the object-space pattern is on screen: per pixel, the Jacobian of its
// texel coordinate (the projection along the normal's nearest axis, the pixel's octave) by
// neighbouring pixels of one surface; its singular values' ratio (anisotropy: 1 for a pattern
// flat to the screen) and the spread of their geometric mean (p90 / p10: 1 for one scale).
// From the geometry, not the shader; the dissolves between axes and octaves are left out.
void objectFlatness(const ImageRGBA32F& eye, const ImageRGBA32F& normal, const CameraMatrices& m, int w, int h, Run& out) {
  const glm::mat4 toObject = glm::inverse(m.view);
  const float pixelSize = 2.0f / (m.projection[1][1] * float(h));
  auto at = [&](int x, int y) { return (std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4; };
  std::vector<double> anis, scales;
  for (int y = 0; y + 1 < h; y += 2)
    for (int x = 0; x + 1 < w; x += 2) {
      const std::size_t i = at(x, y), r = at(x + 1, y), d = at(x, y + 1);
      if (eye.pixels[i + 3] <= 0.0f || eye.pixels[r + 3] <= 0.0f || eye.pixels[d + 3] <= 0.0f) continue;
      const glm::vec3 e(eye.pixels[i], eye.pixels[i + 1], eye.pixels[i + 2]);
      const glm::vec3 er(eye.pixels[r], eye.pixels[r + 1], eye.pixels[r + 2]), ed(eye.pixels[d], eye.pixels[d + 1], eye.pixels[d + 2]);
      const float depth = -e.z;
      if (std::fabs(er.z - e.z) > 0.01f * depth || std::fabs(ed.z - e.z) > 0.01f * depth) continue;  // an edge between surfaces
      const glm::vec3 n = glm::abs(glm::mat3(toObject) * glm::vec3(normal.pixels[i], normal.pixels[i + 1], normal.pixels[i + 2]));
      const int axis = n.x >= n.y && n.x >= n.z ? 0 : (n.y >= n.z ? 1 : 2);
      auto plane = [&](const glm::vec3& eyePoint) {
        const glm::vec3 p = glm::vec3(toObject * glm::vec4(eyePoint, 1.0f));
        return axis == 0 ? glm::vec2(p.y, p.z) : axis == 1 ? glm::vec2(p.z, p.x) : glm::vec2(p.x, p.y);
      };
      const float texels = std::exp2(std::floor(-std::log2(depth * pixelSize)));
      const glm::vec2 dx = (plane(er) - plane(e)) * texels, dy = (plane(ed) - plane(e)) * texels;
      // Singular values of [dx dy] from the eigenvalues of its Gram matrix.
      const double a = glm::dot(dx, dx), b = glm::dot(dx, dy), c = glm::dot(dy, dy);
      const double mid = 0.5 * (a + c), root = std::sqrt(std::max(0.0, 0.25 * (a - c) * (a - c) + b * b));
      const double s1 = std::sqrt(std::max(0.0, mid + root)), s2 = std::sqrt(std::max(0.0, mid - root));
      if (!(s1 > 0.0)) continue;
      anis.push_back(std::min(100.0, s1 / std::max(s2, 1e-9)));
      scales.push_back(std::sqrt(s1 * std::max(s2, 1e-9)));
    }
  if (anis.empty()) return;
  std::sort(anis.begin(), anis.end());
  std::sort(scales.begin(), scales.end());
  out.anisotropy = anis[anis.size() / 2];
  out.scaleSpread = scales[scales.size() * 9 / 10] / std::max(scales[scales.size() / 10], 1e-9);
}

Run runScript(Renderer& r, OffscreenTarget& target, const Mesh& mesh, const Script& sc, PatternSpace space, int frames, int w, int h) {
  Run out;
  OrbitCamera cam(30.0f, 20.0f, 3.0f);
  cam.frame(mesh.radius);
  if (sc.zoom > 1.0f) cam.zoom(2.0f, glm::vec2(0.0f), float(w) / h);  // start further out so the zoom stays on the model
  RenderSettings s;
  s.path = RenderPath::Pixel;
  s.pattern = space;
  r.resetPattern();
  const float aspect = float(w) / float(h);
  std::vector<double> fitMs;
  for (int f = 0; f <= frames; ++f) {
    const CameraMatrices m = cam.matrices(aspect);
    r.lighting().setModelView(m.view);
    const float pos[4] = {2.0f, 2.5f, 3.0f, 1.0f};
    (void)r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos);
    target.bind();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!r.render(m, s, {0, 0, w, h})) std::abort();
    const ImageRGBA8 img = target.readRGBA8();
    const PatternFrame frameNow = space == PatternSpace::Anchored ? r.scene().first()->patterns().frame() : PatternFrame{};
    if (space == PatternSpace::Anchored && f > 0) {
      fitMs.push_back(r.stats().cpuPatternMs);
      out.samples = r.stats().patternSamples;
    }
    // Geometry of this frame, for the slide to the next one.
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    auto ftarget = OffscreenTarget::create(w, h, OffscreenTarget::Format::RGBA32F);
    ftarget->bind();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!r.render(m, RenderSettings{}, {0, 0, w, h}, FrameOutput::EyePosition)) std::abort();
    const ImageRGBA32F geo = ftarget->readRGBA32F();
    if (space == PatternSpace::Object && f == 0) {
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      if (!r.render(m, RenderSettings{}, {0, 0, w, h}, FrameOutput::EyeNormal)) std::abort();
      objectFlatness(geo, ftarget->readRGBA32F(), m, w, h, out);
    }
    // Tone and contrast over the model.
    double sum = 0.0, sum2 = 0.0;
    int covered = 0;
    for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
      if (geo.pixels[i * 4 + 3] == 0.0f) continue;
      const float l = luminance(&img.pixels[i * 4]);
      sum += l;
      sum2 += double(l) * l;
      ++covered;
    }
    const double mean = covered ? sum / covered : 0.0;
    out.meanTone.push_back(float(mean));
    out.contrast.push_back(float(covered ? std::sqrt(std::max(0.0, sum2 / covered - mean * mean)) : 0.0));
    if (f == frames) break;
    // Move the camera, then measure where this frame's surface points and pattern texels go.
    if (sc.orbit != 0.0f) cam.orbit(sc.orbit, 0.0f);
    if (sc.pan != glm::vec2(0.0f)) cam.pan(glm::vec2(2.0f * sc.pan.x / w, -2.0f * sc.pan.y / h), aspect);
    if (sc.zoom != 1.0f) cam.zoom(1.0f / sc.zoom, glm::vec2(0.0f), aspect);
    const CameraMatrices next = cam.matrices(aspect);
    // The pattern's next frame is what the tracker will fit; take it from a render.
    target.bind();
    if (!r.render(next, s, {0, 0, w, h})) std::abort();
    const PatternFrame frameNext = space == PatternSpace::Anchored ? r.scene().first()->patterns().frame() : PatternFrame{};
    // That render advanced the tracker: undo by replaying from a reset is not possible, so the
    // loop below renders `next` again as frame f + 1 (a zero-motion fit, frame unchanged).
    out.slide += test::patternSlide(geo, m, next, space == PatternSpace::Anchored ? &frameNow : nullptr,
                                    space == PatternSpace::Anchored ? &frameNext : nullptr);
    if (space == PatternSpace::Anchored) out.floor += test::leastSimilaritySlide(geo, m, next, 4);
  }
  out.slide /= frames;
  out.floor /= frames;
  if (!fitMs.empty()) {
    std::sort(fitMs.begin(), fitMs.end());
    out.fitMs = fitMs[fitMs.size() / 2];
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<bench::ImageBenchArgs> args = bench::parseImageBenchArgs(argc, argv, "bench_patterns");
  if (!args) return 2;
  const int w = args->width, h = args->height, frames = args->frames;
  const bool quick = args->quick;
  auto ctx = HeadlessContext::create(false);
  if (!ctx) return 1;
  auto target = OffscreenTarget::create(w, h);
  auto renderer = Renderer::create();
  if (!target || !renderer) return 1;
  Renderer& r = **renderer;
  applyDefaultMaterial(r.lighting());
  auto palette = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/crosshatch/crosshatch.palette");
  auto bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  if (!palette || !bunny || !r.palettes().setMain(*palette)) return 1;
  // One palette step: the mean luminance difference between neighbouring entries.
  float step = 0.0f;
  for (std::size_t k = 0; k + 1 < palette->entries.size(); ++k)
    step += std::fabs(glm::dot(palette->entries[k].average - palette->entries[k + 1].average, glm::vec3(0.2126f, 0.7152f, 0.0722f)));
  step /= float(palette->entries.size() - 1);
  struct Scene { const char* name; const Mesh* mesh; };
  std::vector<Scene> scenes = {{"bunny", &*bunny}};
  if (!quick) scenes.push_back({"torus 871K", &bench::largeMesh()});
  const Script scripts[] = {{"orbit 1 deg/frame", 1.0f, {}, 1.0f}, {"pan 3 px/frame", 0.0f, {3.0f, 0.0f}, 1.0f},
                            {"zoom 8x", 0.0f, {}, std::pow(8.0f, 1.0f / float(frames))}};
  std::printf("GL: %s; %dx%d, %d frames per script, pixel path, crosshatch (one step = %.3f luminance)\n\n",
              (*ctx)->description().c_str(), w, h, frames, step);
  std::printf("| mesh | script | pattern | slide px/frame | tone vs screen, worst (steps) | contrast first -> last | fit ms | samples | anisotropy / scale spread |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Scene& scene : scenes) {
    r.scene().setOnly(scene.mesh);
    for (const Script& sc : scripts) {
      const Run screen = runScript(r, *target, *scene.mesh, sc, PatternSpace::Screen, frames, w, h);
      const Run anchored = runScript(r, *target, *scene.mesh, sc, PatternSpace::Anchored, frames, w, h);
      const Run object = runScript(r, *target, *scene.mesh, sc, PatternSpace::Object, frames, w, h);
      for (const Run* run : {&screen, &anchored, &object}) {
        float worst = 0.0f;
        for (std::size_t f = 0; f < run->meanTone.size() && f < screen.meanTone.size(); ++f)
          worst = std::max(worst, std::fabs(run->meanTone[f] - screen.meanTone[f]) / step);
        // The object-space pattern is a function of the surface point: it does not slide (its
        // octave and axis dissolves change which marks show, not where they sit).
        std::string slide = run == &object ? "0 (glued)" : std::to_string(run->slide).substr(0, 5);
        // Anchored: and the least any similarity could slide (what is left is parallax).
        if (run == &anchored) slide += " (least " + std::to_string(run->floor).substr(0, 5) + ")";
        char flat[48];
        std::snprintf(flat, sizeof flat, "%.2f / %.2f", run->anisotropy, run->scaleSpread);
        std::printf("| %s | %s | %s | %s | %.2f | %.3f -> %.3f | %s | %s | %s |\n", scene.name, sc.name,
                    run == &screen ? "screen" : run == &anchored ? "anchored" : "object", slide.c_str(), worst, run->contrast.front(),
                    run->contrast.back(), run != &anchored ? "-" : std::to_string(run->fitMs).substr(0, 5).c_str(),
                    run != &anchored ? "-" : std::to_string(run->samples).c_str(), flat);
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
