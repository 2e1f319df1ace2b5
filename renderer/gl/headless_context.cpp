// EGL surfaceless context creation (see headless_context.h).
#include "renderer/gl/headless_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include "renderer/gl/gl_debug.h"

namespace npr {

Result<std::unique_ptr<HeadlessContext>> HeadlessContext::create(bool debug) {
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
    return Error{"headless rendering needs EGL_MESA_platform_surfaceless (install libegl-mesa0 and libgl1-mesa-dri)"};
  EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (dpy == EGL_NO_DISPLAY) return Error{"eglGetPlatformDisplayEXT(surfaceless) returned no display"};
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) return Error{"eglInitialize failed on the surfaceless display"};
  if (!eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(dpy);
    return Error{"eglBindAPI(EGL_OPENGL_API) failed: this EGL has no desktop OpenGL"};
  }
  // Surfaceless has no window configs: the default EGL_SURFACE_TYPE (window) would match none.
  const EGLint configAttribs[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(dpy, configAttribs, &config, 1, &count) || count == 0) {
    eglTerminate(dpy);
    return Error{"no EGL config supports desktop OpenGL"};
  }
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
  if (ctx == EGL_NO_CONTEXT) {
    eglTerminate(dpy);
    return Error{"could not create an OpenGL 3.3+ core context through EGL"};
  }
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    return Error{"eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context missing?)"};
  }
  std::unique_ptr<HeadlessContext> c(new HeadlessContext());
  c->display_ = dpy;
  c->context_ = ctx;
  if (debug) gl::installDebugOutput();
  return c;
}

HeadlessContext::~HeadlessContext() {
  if (!display_) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

std::string HeadlessContext::description() const {
  return std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))) + " / " +
         reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

}  // namespace npr
