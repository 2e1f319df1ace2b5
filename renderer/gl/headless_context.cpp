// EGL context creation on a device or the surfaceless platform (see headless_context.h).
#include "renderer/gl/headless_context.h"

#include <cstdlib>
#include <algorithm>
#include <optional>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include "renderer/gl/gl_debug.h"
#include "renderer/gl/pass_state.h"

// EGL_EXT_device_query_name, newer than the registry epoxy was generated from.
#ifndef EGL_RENDERER_EXT
#define EGL_RENDERER_EXT 0x335F
#endif
// EGL_EXT_device_drm_render_node, likewise.
#ifndef EGL_DRM_RENDER_NODE_FILE_EXT
#define EGL_DRM_RENDER_NODE_FILE_EXT 0x3377
#endif

namespace npr {
namespace {

struct EglDevices {
  std::vector<EGLDeviceEXT> handles;
  std::vector<GpuDevice> described;
};

EglDevices listDevices() {
  EglDevices out;
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!canEnumerateDevices(client)) return out;
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return out;
  out.handles.resize(static_cast<std::size_t>(std::min(count, 64)));
  if (!eglQueryDevicesEXT(static_cast<EGLint>(out.handles.size()), out.handles.data(), &count)) {
    out.handles.clear();
    return out;
  }
  out.handles.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    GpuDevice d;
    d.index = i;
    const char* ext = eglQueryDeviceStringEXT(out.handles[i], EGL_EXTENSIONS);
    d.software = hasEglExtension(ext, "EGL_MESA_device_software");
    if (hasEglExtension(ext, "EGL_EXT_device_query_name"))
      if (const char* r = eglQueryDeviceStringEXT(out.handles[i], EGL_RENDERER_EXT)) d.name = r;
    if (hasEglExtension(ext, "EGL_EXT_device_drm_render_node"))
      if (const char* node = eglQueryDeviceStringEXT(out.handles[i], EGL_DRM_RENDER_NODE_FILE_EXT)) d.drmNode = node;
    if (d.drmNode.empty() && hasEglExtension(ext, "EGL_EXT_device_drm"))
      if (const char* node = eglQueryDeviceStringEXT(out.handles[i], EGL_DRM_DEVICE_FILE_EXT)) d.drmNode = node;
    out.described.push_back(std::move(d));
  }
  return out;
}

struct Opened {
  EGLDisplay display;
  EGLContext context;
};

// Initialises `dpy` and makes a core context current on it without a surface.
Result<Opened> openOn(EGLDisplay dpy, bool debug) {
  if (dpy == EGL_NO_DISPLAY) return Error{"EGL gave no display"};
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) return Error{"eglInitialize failed"};
  const auto fail = [&](const char* why) -> Result<Opened> {
    eglTerminate(dpy);
    return Error{why};
  };
  if (!eglBindAPI(EGL_OPENGL_API)) return fail("this EGL has no desktop OpenGL (eglBindAPI failed)");
  // No surface is ever made: EGL_SURFACE_TYPE 0 accepts configs with no window bit
  // (surfaceless and device displays may have none).
  const EGLint configAttribs[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(dpy, configAttribs, &config, 1, &count) || count == 0)
    return fail("no EGL config supports desktop OpenGL");
  EGLContext ctx = EGL_NO_CONTEXT;
  for (const auto& version : {std::pair{4, 5}, std::pair{3, 3}}) {
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, version.first,
                                 EGL_CONTEXT_MINOR_VERSION, version.second,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
                                 EGL_NONE};
    ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx != EGL_NO_CONTEXT) break;
  }
  if (ctx == EGL_NO_CONTEXT) return fail("could not create an OpenGL 3.3+ core context");
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    eglDestroyContext(dpy, ctx);
    return fail("eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context missing?)");
  }
  gl::forgetAppliedState();  // a new context holds GL's defaults, not what was applied before
  return Opened{dpy, ctx};
}

Result<Opened> openSurfaceless(bool debug) {
  if (!hasEglExtension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless"))
    return Error{"Mesa's surfaceless EGL platform is missing (install libegl-mesa0 and libgl1-mesa-dri)"};
  return openOn(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), debug);
}

}  // namespace

Result<std::unique_ptr<HeadlessContext>> HeadlessContext::create(bool debug, const GpuRequest& gpu) {
  const EglDevices devices = listDevices();
  auto order = devicesToTry(devices.described, gpu);
  if (!order) return Error{order.error()};

  std::string failures;
  std::optional<Opened> opened;
  std::string via;
  for (int index : *order) {
    const GpuDevice& d = devices.described[static_cast<std::size_t>(index)];
    auto o = openOn(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices.handles[static_cast<std::size_t>(index)], nullptr), debug);
    if (o) {
      opened = *o;
      via = "EGL device " + std::to_string(index) + ": " + deviceLabel(d);
      break;
    }
    failures += "\n  device " + std::to_string(index) + ": " + o.error();
  }
  if (!opened && gpu.kind != GpuRequest::Kind::Automatic && gpu.kind != GpuRequest::Kind::Surfaceless)
    return Error{"--gpu: the device asked for could not give an OpenGL context:" + failures};
  if (!opened) {
    auto o = openSurfaceless(debug);
    if (!o) return Error{"no headless OpenGL context: " + o.error() + failures};
    opened = *o;
    via = "Mesa surfaceless platform";
  }

  std::unique_ptr<HeadlessContext> c(new HeadlessContext());
  c->display_ = opened->display;
  c->context_ = opened->context;
  c->info_ = currentGlInfo();
  c->info_.device = via;
  c->info_.devices = devices.described;
  if (debug) gl::installDebugOutput();
  return c;
}

HeadlessContext::~HeadlessContext() {
  if (!display_) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

std::string HeadlessContext::description() const { return info_.version + " / " + info_.renderer; }

Result<GpuRequest> gpuRequestFromEnvironment() {
  const char* env = std::getenv("NPR_GPU");
  auto r = parseGpuRequest(env ? env : "");
  if (!r) return Error{"NPR_GPU: " + r.error()};
  return r;
}

}  // namespace npr
