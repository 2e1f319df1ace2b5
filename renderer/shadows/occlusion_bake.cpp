// The ambient occlusion bake (see occlusion_bake.h).
#include "renderer/shadows/occlusion_bake.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/core/elapsed.h"
#include "renderer/gl/pass_state.h"
#include "renderer/programs/program_variants.h"
#include "renderer/gl/texture.h"
#include "renderer/gl/texture_target.h"
#include "renderer/gl/texture_units.h"

namespace npr {
namespace {
// The texture unit the bake samples its directions' depth maps on (gl/texture_units.h).
const gl::TextureUnit kBakeDepthUnit = gl::claimTextureUnit();
}  // namespace
namespace {

// Bit-reversed order of 0..n-1 (n rounded up to a power of two, out-of-range skipped): every
// prefix of the Fibonacci sphere taken in this order spreads from pole to pole.
std::vector<int> spreadOrder(int n) {
  int bits = 0;
  while ((1 << bits) < n) ++bits;
  std::vector<int> order;
  for (int i = 0; i < (1 << bits); ++i) {
    int r = 0;
    for (int b = 0; b < bits; ++b)
      if (i & (1 << b)) r |= 1 << (bits - 1 - b);
    if (r < n) order.push_back(r);
  }
  return order;
}

}  // namespace

std::vector<glm::vec3> OcclusionBake::sampleDirections(int count) {
  count = std::clamp(count, 1, 4096);
  // A Fibonacci spiral over the sphere, taken in an order whose every prefix spreads evenly.
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  std::vector<glm::vec3> dirs;
  for (int i : spreadOrder(count)) {
    const double z = 1.0 - 2.0 * (i + 0.5) / count, r = std::sqrt(std::max(0.0, 1.0 - z * z));
    dirs.push_back(glm::vec3(float(r * std::cos(golden * i)), float(z), float(r * std::sin(golden * i))));
  }
  return dirs;
}

Result<std::unique_ptr<OcclusionBake>> OcclusionBake::start(const Mesh& mesh, const GpuMesh& gpuMesh, int directions) {
  std::unique_ptr<OcclusionBake> b(new OcclusionBake());
  b->gpuMesh_ = &gpuMesh;
  b->vertexCount_ = mesh.positions.size();
  b->radius_ = mesh.radius > 0.0f && std::isfinite(mesh.radius) ? mesh.radius : 1.0f;
  b->dirs_ = sampleDirections(directions);
  b->count_ = int(b->dirs_.size());
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  const int w = std::min<int>(maxSize, 4096);
  const std::size_t rows = (b->vertexCount_ + std::size_t(w) - 1) / std::size_t(w);
  if (b->vertexCount_ == 0 || rows > std::size_t(maxSize)) return Error{"ambient occlusion: the mesh has too many vertices for one target"};
  b->targetSize_ = glm::ivec2(w, int(std::max<std::size_t>(rows, 1)));

  b->depth_ = gl::createTexture();
  glBindTexture(GL_TEXTURE_2D, b->depth_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kDepthSize, kDepthSize, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  gl::setDepthCompare(GL_TEXTURE_2D);
  b->accumulation_ = gl::createTexture();
  glBindTexture(GL_TEXTURE_2D, b->accumulation_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, b->targetSize_.x, b->targetSize_.y, 0, GL_RGBA, GL_FLOAT, nullptr);
  gl::setNearestSingleLevel(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);

  GLint previous = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  b->depthFbo_ = gl::createFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, b->depthFbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, b->depth_.id(), 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  b->accumulationFbo_ = gl::createFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, b->accumulationFbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, b->accumulation_.id(), 0);
  glClearColor(0, 0, 0, 0);
  gl::apply(gl::pass::kClearTarget);
  glClear(GL_COLOR_BUFFER_BIT);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  if (!complete) return Error{"ambient occlusion: this GPU cannot render into a float target"};
  if (glGetError() == GL_OUT_OF_MEMORY) return Error{"ambient occlusion: out of GPU memory"};
  return b;
}

Status OcclusionBake::step(double budgetMs, gl::ProgramCache& programs, FrameStats& stats) {
  if (done()) return okStatus();
  const auto t0 = std::chrono::steady_clock::now();
  Result<gl::ShaderProgram*> depthProg = programs.get(gl::ShadowDepthProgram{}, stats.shaderBuilds);
  if (!depthProg) return Error{depthProg.error()};
  Result<gl::ShaderProgram*> bakeProg = programs.get(gl::OcclusionBakeProgram{}, stats.shaderBuilds);
  if (!bakeProg) return Error{bakeProg.error()};
  GLint previous = 0, vp[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glGetIntegerv(GL_VIEWPORT, vp);
  const float r = radius_ * 1.02f;
  const float offset = 2.0f * 2.0f * r / float(kDepthSize);
  while (!done()) {
    const glm::vec3 d = dirs_[static_cast<size_t>(next_)];
    const glm::vec3 up = std::fabs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::mat4 viewProj = glm::ortho(-r, r, -r, r, r, 3.0f * r) * glm::lookAt(d * (2.0f * r), glm::vec3(0.0f), up);
    // (1) the mesh's depth seen from direction d
    glBindFramebuffer(GL_FRAMEBUFFER, depthFbo_.id());
    glViewport(0, 0, kDepthSize, kDepthSize);
    gl::apply(gl::pass::kClearTarget);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    gl::apply(gl::pass::kShadowDepth);
    (*depthProg)->use();
    (*depthProg)->set("uLightViewProjection", viewProj);
    gpuMesh_->drawAll();
    // (2) every vertex adds its sample to its texel
    glBindFramebuffer(GL_FRAMEBUFFER, accumulationFbo_.id());
    glViewport(0, 0, targetSize_.x, targetSize_.y);
    gl::apply(gl::pass::kAccumulate);
    (*bakeProg)->use();
    gl::bindTexture(kBakeDepthUnit, GL_TEXTURE_2D, depth_.id());
    (*bakeProg)->set("uDepth", gl::unitIndex(kBakeDepthUnit));
    (*bakeProg)->set("uDirectionViewProjection", viewProj);
    (*bakeProg)->set("uDirection", d);
    (*bakeProg)->set("uOffset", offset);
    (*bakeProg)->set("uTargetSize", targetSize_);
    gpuMesh_->drawPoints();
    stats.drawCalls += 2;
    ++next_;
    if (budgetMs > 0.0 && msSince(t0) >= budgetMs) break;
  }
  if (done()) {
    std::vector<float> px(std::size_t(targetSize_.x) * std::size_t(targetSize_.y) * 4);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, targetSize_.x, targetSize_.y, GL_RGBA, GL_FLOAT, px.data());
    values_.resize(vertexCount_);
    for (std::size_t i = 0; i < vertexCount_; ++i) {
      const float seen = px[i * 4], total = px[i * 4 + 1];
      values_[i] = total > 0.0f && std::isfinite(seen / total) ? std::clamp(seen / total, 0.0f, 1.0f) : 1.0f;
    }
    depth_.reset();
    accumulation_.reset();
    depthFbo_.reset();
    accumulationFbo_.reset();
  }
  gl::apply(gl::pass::kBackground);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  glViewport(vp[0], vp[1], vp[2], vp[3]);
  ms_ += msSince(t0);
  return okStatus();
}

}  // namespace npr
