// Headless sessions (see headless_session.h).
#include "app/headless/headless_session.h"

#include <cstdio>

namespace npr {

Result<HeadlessSession> openHeadlessSession(bool debug, const GpuRequest& gpu) {
  auto ctx = HeadlessContext::create(debug, gpu);
  if (!ctx) return Error{ctx.error()};
  const GlInfo& info = (*ctx)->info();
  if (info.softwareWhileHardwareExists())
    std::fprintf(stderr, "npr-viewer: warning: rendering on the software rasterizer %s although EGL lists a hardware device:\n%s"
                         "  (choose one with --gpu INDEX|NAME or NPR_GPU)\n",
                 info.renderer.c_str(), describeDevices(info.devices).c_str());
  auto renderer = Renderer::create();
  if (!renderer) return Error{renderer.error()};
  return HeadlessSession{std::move(*ctx), std::move(*renderer)};
}

}  // namespace npr
