// Headless rendering (see headless_run.h).
#include "app/headless_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "app/startup.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/headless_context.h"
#include "renderer/image_io.h"
#include "renderer/offscreen_target.h"

namespace npr {

int runHeadless(const Options& o) {
  auto ctx = HeadlessContext::create(true);
  if (!ctx) {
    std::fprintf(stderr, "npr-viewer: %s\n", ctx.error().c_str());
    return 1;
  }
  auto target = OffscreenTarget::create(o.size.x, o.size.y);
  if (!target) {
    std::fprintf(stderr, "npr-viewer: %s\n", target.error().c_str());
    return 1;
  }
  auto renderer = Renderer::create();
  if (!renderer) {
    std::fprintf(stderr, "npr-viewer: %s\n", renderer.error().c_str());
    return 1;
  }
  ViewerState state;
  if (Status s = startScene(o, state, **renderer); !s) {
    std::fprintf(stderr, "npr-viewer: %s\n", s.error().c_str());
    return 1;
  }
  const int frames = std::max(1, o.frames);
  const float aspect = float(o.size.x) / float(o.size.y);
  std::vector<double> ms;
  target->bind();
  for (int f = 0; f < frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    const CameraMatrices cam = state.camera.matrices(aspect);
    state.applyLight(**renderer, cam);
    target->bind();
    if (Status s = (*renderer)->render(cam, state.settings, {0, 0, o.size.x, o.size.y}); !s) {
      std::fprintf(stderr, "npr-viewer: render failed: %s\n", s.error().c_str());
      return 1;
    }
    finishGpuWork();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  std::fprintf(stderr, "npr-viewer: %d frame(s) of %s at %dx%d, path %s, match %s: median %.2f ms\n", frames,
               state.mesh->report.file.c_str(), o.size.x, o.size.y, renderPathName(state.settings.path),
               matchModeName(state.settings.match), ms[ms.size() / 2]);
  if (!o.screenshot.empty()) {
    if (Status s = writeImage(o.screenshot, target->readRGBA8()); !s) {
      std::fprintf(stderr, "npr-viewer: %s\n", s.error().c_str());
      return 1;
    }
  }
  const int errors = gl::checkErrors("end of headless run");
  if (errors) {
    std::fprintf(stderr, "npr-viewer: %d OpenGL error(s) during the run\n", errors);
    return 1;
  }
  return 0;
}

}  // namespace npr
