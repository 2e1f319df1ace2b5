// The renderer facade (see renderer.h): what a frame is, in order. The work is in the passes.
#include "renderer/renderer.h"

#include <chrono>

#include "renderer/core/elapsed.h"
#include "renderer/gl/pass_state.h"
#include "renderer/passes/background_pass.h"
#include "renderer/passes/marker_pass.h"
#include "renderer/paths/render_pass.h"

namespace npr {

Result<std::unique_ptr<Renderer>> Renderer::create() {
  if (epoxy_gl_version() < 33) return Error{"the renderer needs OpenGL 3.3 or later; this context is " + std::to_string(epoxy_gl_version())};
  std::unique_ptr<Renderer> r(new Renderer());
  r->emptyVao_ = gl::createVertexArray();
  for (const PathInfo& info : renderPaths()) r->paths_.push_back(info.create());
  return r;
}

Renderer::~Renderer() = default;

void Renderer::setMesh(const Mesh* mesh) {
  mesh_ = mesh && !mesh->indices.empty() ? mesh : nullptr;
  gpuMesh_.clear();
  materials_.clear();
  triangles_.setMesh(mesh_);
  lines_.setMesh(mesh_);
  if (!mesh_) return;
  gpuMesh_.upload(*mesh_);
  materials_.upload(*mesh_);
  stats_.bufferUploads += 3;
}

Status Renderer::setPalette(const Palette& palette) {
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  palette_ = std::move(*uploaded);
  stats_.bufferUploads += 1;
  return okStatus();
}

void Renderer::collectGpuTime() {
  if (std::optional<double> ms = timer_.collect()) stats_.gpuMs = *ms;
}

Status Renderer::prepare(const RenderSettings& s) {
  if (!palette_ && pathInfo(s.path).usesPalette) return Error{"no palette loaded"};
  if (palette_) return palette_->updateMatcher(s.match, s.rangeScale, s.bands, stats_);
  return okStatus();
}

void Renderer::clearViewport(const glm::ivec4& viewport) {
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  glScissor(viewport.x, viewport.y, viewport.z, viewport.w);
  gl::apply(gl::pass::kClearViewport);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

Status Renderer::drawPath(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport, gl::MeshOutput output) {
  if (!mesh_) return okStatus();
  if (s.materials) materials_.update(*mesh_, lighting_, stats_);
  FrameContext frame{camera, viewport, s, lighting_, gpuMesh_, *mesh_, materials_, palette_.get(), triangles_, programs_, stats_, emptyVao_, output};
  return paths_[pathIndex(s.path)]->draw(frame);
}

Status Renderer::render(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  const auto frameStart = std::chrono::steady_clock::now();
  stats_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();  // minimised window: nothing to draw
  if (Status st = prepare(s); !st) return st;
  collectGpuTime();
  timer_.begin();
  clearViewport(viewport);
  Status result = drawBackground(palette_.get(), programs_, emptyVao_, stats_);
  if (result) result = drawPath(camera, s, viewport, gl::MeshOutput::Colour);
  if (result && mesh_) result = imageEdges_.draw(gpuMesh_, camera, s.lines, viewport, programs_, emptyVao_, stats_);
  if (result && mesh_) result = lines_.draw(camera, s.lines, viewport, programs_, stats_);
  timer_.end();
  gl::restoreDefaults();
  stats_.cpuFrameMs = msSince(frameStart);
  return result;
}

Status Renderer::renderSelection(const CameraMatrices& camera, const RenderSettings& s, SelectionOutput output,
                                 const glm::ivec4& viewport) {
  stats_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();
  if (Status st = prepare(s); !st) return st;
  clearViewport(viewport);
  const Status result = drawPath(camera, s, viewport, output == SelectionOutput::Entry ? gl::MeshOutput::Entry : gl::MeshOutput::Blend);
  gl::restoreDefaults();
  return result;
}

Status Renderer::renderGeometry(const CameraMatrices& camera, GeometryOutput output, const glm::ivec4& viewport) {
  stats_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();
  clearViewport(viewport);
  const Status result = mesh_ ? drawGeometry(gpuMesh_, camera, output, programs_, stats_) : okStatus();
  gl::restoreDefaults();
  return result;
}

Status Renderer::drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour, float pixels,
                            const glm::ivec4& viewport) {
  return npr::drawMarker(camera, worldPosition, colour, pixels, viewport, programs_, emptyVao_, stats_);
}

}  // namespace npr
