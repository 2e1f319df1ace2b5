// Painterly brush strokes (see brush_stroke_pass.h).
#include "renderer/strokes/brush_stroke_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture_units.h"
#include "renderer/lighting/lighting_model.h"
#include "renderer/lighting/lighting_uniforms.h"
#include "renderer/strokes/brush_shapes.h"

namespace npr {
namespace {
// This file's samplers' texture units (gl/texture_units.h).
const gl::TextureUnit kBrushUnit = gl::claimTextureUnit();  // painterly strokes' brush coverage
}  // namespace

void BrushStrokePass::setMesh(const Mesh* mesh, const Mesh* rest) {
  mesh_ = mesh;
  rest_ = rest && rest != mesh && rest->positions.size() == mesh->positions.size() ? rest : nullptr;
  seededDensity_ = -1.0f;
  seededBudget_ = -1;
  count_ = 0;
  particles_.clear();
  anchors_.clear();
  moved_ = false;
}

Status BrushStrokePass::draw(const CameraMatrices& camera, float sceneScale, const StrokeSettings& st, const LightingState& lighting, const GpuPalette& palette,
                             MatchMode match, const std::vector<glm::vec3>& directions, bool fade, const glm::ivec4& viewport,
                             gl::ProgramCache& programs, FrameStats& stats) {
  if (!st.on || !mesh_) return okStatus();
  if (!vao_) {
    vao_ = gl::createVertexArray();
    instances_ = gl::createBuffer();
    brush_ = gl::createTexture();
    const std::vector<std::uint8_t> coverage = brushCoverage();
    gl::bindTexture(kBrushUnit, GL_TEXTURE_2D, brush_.id());
    glActiveTexture(GL_TEXTURE0 + GLenum(kBrushUnit.index));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, kBrushLength * kBrushes, kBrushWidth, 0, GL_RED, GL_UNSIGNED_BYTE, coverage.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glActiveTexture(GL_TEXTURE0);
  }
  const float density = std::clamp(st.density, StrokeSettings::kMinDensity, StrokeSettings::kMaxDensity);
  const int budget = std::clamp(st.budget, 0, StrokeSettings::kMaxBudget);
  const bool withField = directions.size() == mesh_->positions.size();
  if (density != seededDensity_ || budget != seededBudget_ || withField != seededWithField_) {
    const float scale = std::isfinite(sceneScale) && sceneScale > 0.0f ? sceneScale : 1.0f;
    const StrokeSeeding seeding = seedStrokes(rest_ ? *rest_ : *mesh_, density * scale * scale, budget, directions);
    ++stats.meshCachesBuilt;
    static_assert(sizeof(StrokeParticle) == 11 * sizeof(float), "the instance layout below reads 11 floats per stroke");
    gl::uploadBuffer(instances_, seeding.particles.data(), seeding.particles.size() * sizeof(StrokeParticle), GL_STATIC_DRAW);
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, instances_.id());
    const GLsizei stride = sizeof(StrokeParticle);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(StrokeParticle, position)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(StrokeParticle, normal)));
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(StrokeParticle, direction)));
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(StrokeParticle, rank)));
    for (GLuint a = 0; a < 4; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribDivisor(a, 1);
    }
    count_ = seeding.particles.size();
    particles_ = seeding.particles;
    anchors_ = seeding.anchors;
    moved_ = rest_ != nullptr;  // seeded at rest: carried to the pose below
    seedMs_ = seeding.ms;
    seededDensity_ = density;
    seededBudget_ = budget;
    seededWithField_ = withField;
    ++stats.bufferUploads;
  }
  if (moved_ && count_ > 0) {
    placeStrokes(*mesh_, directions, anchors_, particles_);  // directions read only when one per vertex
    gl::updateBuffer(instances_, particles_.data(), particles_.size() * sizeof(StrokeParticle));
    ++stats.bufferUploads;
  }
  moved_ = false;
  if (count_ == 0) return okStatus();

  const gl::PaletteVariant pv = palette.matchingVariant(match);
  Result<gl::ShaderProgram*> prog = programs.get(gl::StrokeProgram{lighting.features(), pv}, stats.shaderBuilds);
  if (!prog) return Error{prog.error()};
  gl::ShaderProgram& p = **prog;
  gl::apply(gl::pass::kStrokes);
  p.use();
  p.set("uModelView", camera.view);
  p.set("uProjection", camera.projection);
  p.set("uNormalMatrix", glm::transpose(glm::inverse(glm::mat3(camera.view))));
  p.set("uViewport", glm::vec2(viewport.z, viewport.w));
  p.set("uStrokeSize", glm::clamp(glm::vec2(st.length, st.width), glm::vec2(1.0f), glm::vec2(StrokeSettings::kMaxSize)));
  // Every stroke is drawn out to the distance the viewer frames the model at (3 radii).
  p.set("uKeepDepth", 3.0f * mesh_->radius);
  p.set("uFadeBand", fade ? 0.3f : 0.0f);
  glm::vec4 light(0, 0, 1, 0);
  for (int i = 0; i < kMaxLights; ++i)
    if (lighting.light(i).enabled) {
      light = lighting.light(i).position;
      break;
    }
  p.set("uLightEye", glm::vec3(light));
  p.set("uLightPositional", light.w != 0.0f ? 1.0f : 0.0f);
  uploadLightingUniforms(p, prepareLighting<float>(lighting));
  palette.bindMatching(p);
  const std::vector<glm::vec3>& averages = palette.averages();
  p.setArray("uEntryColour", averages.data(), int(averages.size()));
  gl::bindTexture(kBrushUnit, GL_TEXTURE_2D, brush_.id());
  p.set("uBrush", gl::unitIndex(kBrushUnit));
  glBindVertexArray(vao_.id());
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(count_));
  ++stats.drawCalls;
  return okStatus();
}

}  // namespace npr
