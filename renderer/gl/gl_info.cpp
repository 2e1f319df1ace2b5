// The current context's description (see gl_info.h).
#include "renderer/gl/gl_info.h"

#include <epoxy/gl.h>

namespace npr {
namespace {

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

bool GlInfo::softwareWhileHardwareExists() const {
  if (!software) return false;
  for (const GpuDevice& d : devices)
    if (!d.software) return true;
  return false;
}

std::string GlInfo::line() const {
  std::string s = "GL_VENDOR " + vendor + "; GL_RENDERER " + renderer + "; GL_VERSION " + version;
  if (!device.empty()) s += "; via " + device;
  return s;
}

GlInfo currentGlInfo() {
  GlInfo info;
  info.vendor = glString(GL_VENDOR);
  info.renderer = glString(GL_RENDERER);
  info.version = glString(GL_VERSION);
  info.software = isSoftwareRenderer(info.renderer);
  return info;
}

}  // namespace npr
