// Move-only owners of OpenGL object names: a GL object is freed exactly once, when its owner
// dies. A default-constructed handle owns nothing (name 0), like Magnum's NoCreate state.
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <utility>

namespace npr::gl {

template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint name) : name_(name) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : name_(std::exchange(o.name_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      name_ = std::exchange(o.name_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint id() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  GLuint release() { return std::exchange(name_, 0); }
  void reset() {
    if (name_) Delete(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
};

namespace detail {
inline void deleteBuffer(GLuint n) { glDeleteBuffers(1, &n); }
inline void deleteVertexArray(GLuint n) { glDeleteVertexArrays(1, &n); }
inline void deleteTexture(GLuint n) { glDeleteTextures(1, &n); }
inline void deleteFramebuffer(GLuint n) { glDeleteFramebuffers(1, &n); }
inline void deleteRenderbuffer(GLuint n) { glDeleteRenderbuffers(1, &n); }
inline void deleteQuery(GLuint n) { glDeleteQueries(1, &n); }
inline void deleteProgram(GLuint n) { glDeleteProgram(n); }
inline void deleteShader(GLuint n) { glDeleteShader(n); }
}  // namespace detail

using Buffer = Handle<detail::deleteBuffer>;
using VertexArray = Handle<detail::deleteVertexArray>;
using Texture = Handle<detail::deleteTexture>;
using Framebuffer = Handle<detail::deleteFramebuffer>;
using Renderbuffer = Handle<detail::deleteRenderbuffer>;
using Query = Handle<detail::deleteQuery>;
using Program = Handle<detail::deleteProgram>;
using Shader = Handle<detail::deleteShader>;

inline Buffer createBuffer() { GLuint n = 0; glGenBuffers(1, &n); return Buffer(n); }
inline VertexArray createVertexArray() { GLuint n = 0; glGenVertexArrays(1, &n); return VertexArray(n); }
inline Texture createTexture() { GLuint n = 0; glGenTextures(1, &n); return Texture(n); }
inline Framebuffer createFramebuffer() { GLuint n = 0; glGenFramebuffers(1, &n); return Framebuffer(n); }
inline Renderbuffer createRenderbuffer() { GLuint n = 0; glGenRenderbuffers(1, &n); return Renderbuffer(n); }
inline Query createQuery() { GLuint n = 0; glGenQueries(1, &n); return Query(n); }

// Replaces `buffer`'s contents. Goes through the copy-write target, so neither the array-buffer
// binding nor any vertex array's element binding changes.
inline void uploadBuffer(const Buffer& buffer, const void* data, std::size_t bytes, GLenum usage) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffer.id());
  glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), data, usage);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}
// New contents for the first `bytes` of a buffer already that large (a posed mesh's vertices).
inline void updateBuffer(const Buffer& buffer, const void* data, std::size_t bytes) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffer.id());
  glBufferSubData(GL_COPY_WRITE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}

}  // namespace npr::gl
