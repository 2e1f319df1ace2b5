// What hatching orientation gains and costs, headless:
//  - field: the direction field's median angle to the analytic principal directions on the
//    generated cylinder, torus and ellipsoid (where |k1| > 2 |k2|), and its computation time on
//    those and on the 871K-triangle torus (median of 3);
//  - alignment: the rendered frame's local stroke orientation (structure tensor of the output)
//    against the wanted angles, median over pixels with coherent strokes, per path, with the
//    one-direction hatch palette, for the torus and the bunny (and `none` as the yardstick);
//  - stability: over a 1-degree-per-frame orbit, the share of surface points whose orientation
//    step jumps by more than one between frames (mean and worst frame).
// Frame cost (`--orient curvature` against `none`) is bench_frames --orient.
// Run: build/tests/bench/bench_orientation [--size WxH] [--frames N] [--quick]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench_common.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/renderer.h"
#include "support/analytic_surfaces.h"
#include "support/stroke_alignment.h"

using namespace npr;

namespace {

double medianOf(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

template <class Image>
Image readInto(int w, int h, const std::function<Status(const glm::ivec4&)>& draw) {
  constexpr bool floats = std::is_same_v<Image, ImageRGBA32F>;
  auto t = OffscreenTarget::create(w, h, floats ? OffscreenTarget::Format::RGBA32F : OffscreenTarget::Format::RGBA8);
  if (!t) std::abort();
  t->clear(glm::vec4(0.0f));
  if (Status st = draw({0, 0, w, h}); !st) {
    std::fprintf(stderr, "bench_orientation: %s\n", st.error().c_str());
    std::exit(1);
  }
  if constexpr (floats) return t->readRGBA32F();
  else return t->readRGBA8();
}

void setLight(Renderer& r, const CameraMatrices& m) {
  r.lighting().setModelView(m.view);
  const float pos[4] = {2.0f, 2.5f, 3.0f, 1.0f};
  (void)r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos);
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<bench::ImageBenchArgs> args = bench::parseImageBenchArgs(argc, argv, "bench_orientation");
  if (!args) return 2;
  const int w = args->width, h = args->height, frames = args->frames;
  const bool quick = args->quick;

  std::printf("## Direction field against analytic principal directions\n\n");
  std::printf("| surface | triangles | vertices compared | median error (deg) | field ms |\n|---|---|---|---|---|\n");
  const glm::vec3 radii(1.0f, 0.7f, 0.45f);
  struct Surface {
    const char* name;
    Mesh mesh;
    std::function<test::Principal(const glm::vec3&)> analytic;
  };
  std::vector<Surface> surfaces;
  // Turned off the up axis, which the field's guide follows where curvature is weak.
  const glm::mat3 turn = test::obliqueRotation();
  auto onEllipsoid = [radii](const glm::vec3& p) { return test::ellipsoidPrincipal(p, radii); };
  surfaces.push_back({"cylinder", test::rotatedMesh(cylinder(96, 48), turn), test::rotatedPrincipal(test::cylinderPrincipal, turn)});
  surfaces.push_back({"torus", test::rotatedMesh(torus(160, 80), turn), test::rotatedPrincipal(test::torusPrincipal, turn)});
  surfaces.push_back({"ellipsoid", test::rotatedMesh(ellipsoid(160, 80, radii), turn), test::rotatedPrincipal(onEllipsoid, turn)});
  // The grids above run along the principal directions; a subdivided icosahedron stretched into
  // the same ellipsoid does not.
  Mesh stretched = icosphere(5);
  for (glm::vec3& p : stretched.positions) p *= radii;
  surfaces.push_back({"ellipsoid (stretched icosphere)", test::rotatedMesh(std::move(stretched), turn), test::rotatedPrincipal(onEllipsoid, turn)});
  if (!quick) surfaces.push_back({"torus 871K", bench::largeMesh(), test::torusPrincipal});
  for (const Surface& s : surfaces) {
    std::vector<double> ms;
    DirectionField field;
    for (int k = 0; k < 3; ++k) {
      field = computeDirectionField(s.mesh);
      ms.push_back(field.ms);
    }
    const test::FieldError e = test::fieldError(s.mesh, field.directions, s.analytic);
    std::printf("| %s | %zu | %zu | %.2f | %.1f |\n", s.name, s.mesh.triangleCount(), e.vertices, e.medianDegrees, medianOf(ms));
    std::fflush(stdout);
  }

  auto ctx = HeadlessContext::create(false);
  if (!ctx) {
    std::fprintf(stderr, "%s\n", ctx.error().c_str());
    return 1;
  }
  auto renderer = Renderer::create();
  if (!renderer) return 1;
  Renderer& r = **renderer;
  applyDefaultMaterial(r.lighting());
  auto hatch = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/hatch/hatch.palette");
  auto bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  if (!hatch || !bunny || !r.palettes().setMain(*hatch)) return 1;
  const Mesh smallTorus = torus(160, 80);
  struct Scene { const char* name; const Mesh* mesh; };
  std::vector<Scene> scenes = {{"torus", &smallTorus}, {"bunny", &*bunny}};
  const float aspect = float(w) / float(h);

  std::printf("\n## Strokes in the image against the wanted angles (%dx%d, hatch palette, curvature)\n\n", w, h);
  std::printf("| mesh | path | median error (deg) | pixels | with none: error to the field (deg) |\n|---|---|---|---|---|\n");
  for (const Scene& sc : scenes) {
    r.scene().setOnly(sc.mesh);
    OrbitCamera cam(30.0f, 25.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    const CameraMatrices m = cam.matrices(aspect);
    setLight(r, m);
    for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Smooth, RenderPath::Triangle, RenderPath::Stencil}) {
      RenderSettings s, none;
      s.path = none.path = path;
      s.orient.source = OrientSource::Curvature;
      const ImageRGBA8 img = readInto<ImageRGBA8>(w, h, [&](const glm::ivec4& vp) { return r.render(m, s, vp); });
      const ImageRGBA8 plain = readInto<ImageRGBA8>(w, h, [&](const glm::ivec4& vp) { return r.render(m, none, vp); });
      const ImageRGBA32F wanted = readInto<ImageRGBA32F>(w, h, [&](const glm::ivec4& vp) { return r.render(m, s, vp, FrameOutput::StrokeAngles); });
      const test::Alignment a = test::strokeAlignment(img, wanted), b = test::strokeAlignment(plain, wanted);
      std::printf("| %s | %s | %.2f | %zu | %.2f |\n", sc.name, pathInfo(path).name, a.medianDegrees, a.pixels, b.medianDegrees);
      std::fflush(stdout);
    }
  }

  std::printf("\n## Step stability under a 1 degree/frame orbit (%d frames, %d steps)\n\n", frames, OrientSettings{}.bins);
  std::printf("| mesh | mean share of points jumping > 1 step | worst frame | points compared per frame |\n|---|---|---|---|\n");
  for (const Scene& sc : scenes) {
    r.scene().setOnly(sc.mesh);
    OrbitCamera cam(30.0f, 25.0f, 3.0f);
    cam.frame(sc.mesh->radius);
    RenderSettings s;
    s.orient.source = OrientSource::Curvature;
    CameraMatrices prev = cam.matrices(aspect);
    ImageRGBA32F prevAngles = readInto<ImageRGBA32F>(w, h, [&](const glm::ivec4& vp) { return r.render(prev, s, vp, FrameOutput::StrokeAngles); });
    ImageRGBA32F prevEye = readInto<ImageRGBA32F>(w, h, [&](const glm::ivec4& vp) { return r.render(prev, RenderSettings{}, vp, FrameOutput::EyePosition); });
    double sum = 0.0, worst = 0.0;
    std::size_t compared = 0;
    for (int f = 0; f < frames; ++f) {
      cam.orbit(1.0f, 0.0f);
      const CameraMatrices next = cam.matrices(aspect);
      ImageRGBA32F angles = readInto<ImageRGBA32F>(w, h, [&](const glm::ivec4& vp) { return r.render(next, s, vp, FrameOutput::StrokeAngles); });
      ImageRGBA32F eye = readInto<ImageRGBA32F>(w, h, [&](const glm::ivec4& vp) { return r.render(next, RenderSettings{}, vp, FrameOutput::EyePosition); });
      const double j = test::stepJumpFraction(prevAngles, prevEye, prev, angles, eye, next, s.orient.bins, 0.0f, &compared);
      sum += j;
      worst = std::max(worst, j);
      prev = next;
      prevAngles = std::move(angles);
      prevEye = std::move(eye);
    }
    std::printf("| %s | %.3f%% | %.3f%% | %zu |\n", sc.name, 100.0 * sum / frames, 100.0 * worst, compared);
    std::fflush(stdout);
  }
  return 0;
}
