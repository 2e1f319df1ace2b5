// KHR_debug callback and error bookkeeping (see gl_debug.h).
#include "renderer/gl/gl_debug.h"

#include <epoxy/gl.h>

#include <atomic>
#include <cstdio>
#include <mutex>

namespace npr::gl {
namespace {

std::atomic<int> g_errors{0};
std::mutex g_mutex;
std::vector<std::string> g_messages;

void record(const std::string& msg) {
  ++g_errors;
  std::lock_guard<std::mutex> lock(g_mutex);
  if (g_messages.size() < 64) g_messages.push_back(msg);
  std::fprintf(stderr, "GL error: %s\n", msg.c_str());
}

void GLAPIENTRY onDebugMessage(GLenum /*source*/, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* /*user*/) {
  if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH)
    record("[" + std::to_string(id) + "] " + std::string(message, length > 0 ? static_cast<size_t>(length) : 0));
}

}  // namespace

bool installDebugOutput() {
  if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return false;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
  return true;
}

void reportError(const std::string& message) { record(message); }

int errorCount() { return g_errors.load(); }

std::vector<std::string> errorMessages() {
  std::lock_guard<std::mutex> lock(g_mutex);
  return g_messages;
}

void resetErrors() {
  g_errors = 0;
  std::lock_guard<std::mutex> lock(g_mutex);
  g_messages.clear();
}

int checkErrors(const char* where) {
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) record(std::string(where) + ": glGetError " + std::to_string(e));
  return g_errors.load();
}

}  // namespace npr::gl
