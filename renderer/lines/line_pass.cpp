// Feature-line drawing (see line_pass.h).
#include "renderer/lines/line_pass.h"

#include <algorithm>
#include <chrono>
#include <cstdint>

#include "renderer/core/elapsed.h"
#include "renderer/gl/pass_state.h"

namespace npr {
void LinePass::setMesh(const Mesh* mesh) {
  mesh_ = mesh;
  edges_.reset();
  uploadedCreaseAngle_ = -1.0f;
  silhouetteEye_ = glm::vec3(NAN);
  staticCount_ = creaseCount_ = silhouetteCount_ = 0;
}

void LinePass::geometryChanged() {
  if (edges_ && mesh_) edges_->updatePositions(*mesh_);
  uploadedCreaseAngle_ = -1.0f;
  silhouetteEye_ = glm::vec3(NAN);
}

Status LinePass::draw(const CameraMatrices& camera, const LineSettings& ls, const glm::ivec4& viewport, gl::ProgramCache& programs,
                      FrameStats& stats) {
  if (!ls.objectSpace() || !mesh_) return okStatus();
  const auto t0 = std::chrono::steady_clock::now();
  if (!edges_) {
    edges_ = std::make_unique<FeatureEdges>(*mesh_);
    ++stats.meshCachesBuilt;
  }
  if (!vao_) {
    vao_ = gl::createVertexArray();
    staticLines_ = gl::createBuffer();
    silhouettes_ = gl::createBuffer();
  }
  if ((ls.creases || ls.boundaries || ls.materials) && uploadedCreaseAngle_ != ls.creaseAngle) {
    // Static lines are creases, then boundaries, then material boundaries: the parts asked for
    // are drawn as ranges.
    const auto& lines = edges_->staticLines(ls.creaseAngle);
    gl::uploadBuffer(staticLines_, lines.data(), lines.size() * sizeof(FeatureLine), GL_STATIC_DRAW);
    staticCount_ = lines.size();
    const auto count = [&](EdgeKind k) {
      return static_cast<std::size_t>(std::count_if(lines.begin(), lines.end(), [k](const FeatureLine& l) { return l.kind == float(k); }));
    };
    creaseCount_ = count(EdgeKind::Crease);
    boundaryCount_ = count(EdgeKind::Boundary);
    uploadedCreaseAngle_ = ls.creaseAngle;
    ++stats.bufferUploads;
  }
  const glm::vec3 eye = glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 0, 0, 1));
  if (ls.silhouettes && !(eye == silhouetteEye_)) {
    const auto& lines = edges_->silhouettes(eye);
    gl::uploadBuffer(silhouettes_, lines.data(), lines.size() * sizeof(FeatureLine), GL_STREAM_DRAW);
    silhouetteCount_ = lines.size();
    silhouetteEye_ = eye;
    ++stats.bufferUploads;
  }
  stats.cpuLinesMs += msSince(t0);

  // The visible parts, then (--hidden-lines) the hidden ones, dashed, where the surface is in
  // front of them.
  for (const bool hidden : {false, true}) {
    if (hidden && !ls.hidden) break;
    Result<gl::ShaderProgram*> prog = programs.get(gl::LineProgram{ls.sketchy && !hidden, ls.depthFalloff, hidden}, stats.shaderBuilds);
    if (!prog) return Error{prog.error()};
    gl::ShaderProgram& p = **prog;
    gl::apply(hidden ? gl::pass::kHiddenLines : gl::pass::kLines);
    p.use();
    p.set("uModelViewProjection", camera.projection * camera.view);
    p.set("uViewport", glm::vec2(viewport.z, viewport.w));
    p.set("uWidth", std::max(hidden ? 0.6f * ls.width : ls.width, 0.5f));
    const glm::vec3 colours[4] = {ls.silhouetteColour, ls.creaseColour, ls.boundaryColour, ls.materialColour};
    p.setArray("uColours", colours, 4);
    p.set("uFalloffDepth", glm::length(eye));
    glBindVertexArray(vao_.id());
    drawKinds(ls, ls.sketchy && !hidden ? 3 : 1, stats);
  }
  return okStatus();
}

void LinePass::drawKinds(const LineSettings& ls, int repeat, FrameStats& stats) {
  // Sketchy lines draw each edge three times, jittered differently in the shader.
  auto drawRange = [&](const gl::Buffer& buffer, std::size_t first, std::size_t count) {
    if (count == 0) return;
    glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
    const auto base = static_cast<std::uintptr_t>(first * sizeof(FeatureLine));
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(FeatureLine), reinterpret_cast<void*>(base + offsetof(FeatureLine, a)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(FeatureLine), reinterpret_cast<void*>(base + offsetof(FeatureLine, b)));
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(FeatureLine), reinterpret_cast<void*>(base + offsetof(FeatureLine, kind)));
    for (GLuint a = 0; a < 3; ++a) glVertexAttribDivisor(a, GLuint(repeat));
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(count) * repeat);
    stats.lines += static_cast<int>(count);
    ++stats.drawCalls;
  };
  if (ls.silhouettes) drawRange(silhouettes_, 0, silhouetteCount_);
  if (ls.creases) drawRange(staticLines_, 0, creaseCount_);
  if (ls.boundaries) drawRange(staticLines_, creaseCount_, boundaryCount_);
  if (ls.materials) drawRange(staticLines_, creaseCount_ + boundaryCount_, staticCount_ - creaseCount_ - boundaryCount_);
}

std::vector<FeatureLine> LinePass::lines(const CameraMatrices& camera, const LineSettings& ls) {
  std::vector<FeatureLine> out;
  if (!mesh_ || !ls.objectSpace()) return out;
  if (!edges_) edges_ = std::make_unique<FeatureEdges>(*mesh_);
  if (ls.silhouettes) {
    const glm::vec3 eye = glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 0, 0, 1));
    const auto& s = edges_->silhouettes(eye);
    out.insert(out.end(), s.begin(), s.end());
    silhouetteEye_ = glm::vec3(NAN);  // the uploaded silhouettes may be another eye's now
  }
  for (const FeatureLine& l : edges_->staticLines(ls.creaseAngle)) {
    const auto kind = static_cast<EdgeKind>(int(l.kind + 0.5f));
    if ((kind == EdgeKind::Crease && ls.creases) || (kind == EdgeKind::Boundary && ls.boundaries) || (kind == EdgeKind::Material && ls.materials))
      out.push_back(l);
  }
  return out;
}

}  // namespace npr
