// Shadow map fitting, drawing and binding (see shadow_maps.h).
#include "renderer/shadows/shadow_maps.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture_target.h"
#include "renderer/gl/texture_units.h"

namespace npr {
namespace {

glm::vec3 upFor(const glm::vec3& forward) {
  return std::fabs(forward.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

}  // namespace

void ShadowMaps::clear() {
  maps_.clear();
  depth_.reset();
  fbo_.reset();
  size_ = layerCount_ = allocatedLayers_ = 0;
  sceneVersion_ = ~0u;
}

Status ShadowMaps::update(const LightingState& lighting, const glm::mat4& view, const ShadowScene& scene, gl::ProgramCache& programs,
                          FrameStats& stats) {
  const glm::mat4 toModel = glm::inverse(view);
  const glm::mat3 toModel3(toModel);
  // Fit a map to each enabled light.
  std::vector<LightMap> maps;
  int layers = 0;
  bool anyPoint = false;
  if (lighting.lightingEnabled())
    for (int i = 0; i < kMaxLights; ++i) {
      const Light& l = lighting.light(i);
      if (!l.enabled) continue;
      LightMap m;
      const bool positional = l.position.w != 0.0f;
      if (!positional) {
        const glm::vec3 dir = glm::normalize(toModel3 * glm::vec3(l.position));
        m.key = glm::vec4(dir, 0.0f);
      } else {
        m.positionModel = glm::vec3(toModel * glm::vec4(glm::vec3(l.position) / l.position.w, 1.0f));
        m.key = glm::vec4(m.positionModel, 1.0f);
        if (l.spotCutoff < 90.0f) {
          m.spotKey = glm::vec4(glm::normalize(toModel3 * l.spotDirection), l.spotCutoff);
        } else {
          // A point light outside every caster needs one map, looking at the casters: what it
          // does not see has nothing between it and the light. Inside, six.
          const glm::vec3 toCentre = scene.centre - m.positionModel;
          const float d = glm::length(toCentre), cr = std::max(scene.casterRadius, 1e-6f) * 1.02f;
          if (d > 1.05f * cr) m.spotKey = glm::vec4(toCentre / d, glm::degrees(std::asin(cr / d)));
          else m.point = true;
        }
      }
      if (!std::isfinite(m.key.x) || !std::isfinite(m.key.y) || !std::isfinite(m.key.z)) {
        maps.push_back(m);  // an unusable light (zero direction): unshadowed
        continue;
      }
      m.firstLayer = layers;
      layers += m.point ? 6 : 1;
      anyPoint = anyPoint || m.point;
      maps.push_back(m);
    }
  const int size = anyPoint ? kPointSize : kSize;
  // Nothing moved: the maps stand.
  bool same = scene.version == sceneVersion_ && size == size_ && maps.size() == maps_.size() && layers == layerCount_;
  for (std::size_t k = 0; same && k < maps.size(); ++k) same = maps[k].key == maps_[k].key && maps[k].spotKey == maps_[k].spotKey;
  if (same) return okStatus();

  const float cr = std::max(scene.casterRadius, 1e-6f) * 1.02f, sr = std::max(scene.sceneRadius, cr);
  for (LightMap& m : maps) {
    if (m.firstLayer < 0) continue;
    if (m.key.w == 0.0f) {
      // Directional: orthographic over the casters' sphere, deep enough for every receiver.
      const glm::vec3 dir(m.key);
      const glm::vec3 eye = scene.centre + dir * (2.0f * sr);
      const glm::mat4 v = glm::lookAt(eye, scene.centre, upFor(dir));
      m.viewProjection[0] = glm::ortho(-cr, cr, -cr, cr, sr, 3.0f * sr) * v;
      m.texelSize = 2.0f * cr / float(size);
      continue;
    }
    const float dist = glm::length(m.positionModel - scene.centre);
    const float nearPlane = std::max(1e-3f * sr, dist - sr), farPlane = dist + sr;
    m.perspective = true;
    if (m.point) {
      const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      const glm::mat4 proj = glm::perspective(float(M_PI / 2.0), 1.0f, nearPlane, farPlane);
      for (int f = 0; f < 6; ++f) m.viewProjection[size_t(f)] = proj * glm::lookAt(m.positionModel, m.positionModel + axes[f], upFor(axes[f]));
      m.texelSize = 2.0f / float(size);
    } else {
      const float fov = std::min(2.0f * glm::radians(m.spotKey.w) + 0.1f, glm::radians(170.0f));
      const glm::vec3 dir(m.spotKey);
      m.viewProjection[0] = glm::perspective(fov, 1.0f, nearPlane, farPlane) * glm::lookAt(m.positionModel, m.positionModel + dir, upFor(dir));
      m.texelSize = 2.0f * std::tan(0.5f * fov) / float(size);
    }
  }

  if (layers > 0 && (size != size_ || layers > allocatedLayers_ || !depth_.id())) {
    depth_ = gl::createTexture();
    glActiveTexture(GL_TEXTURE0 + gl::unitIndex(kShadowMapsUnit));
    glBindTexture(GL_TEXTURE_2D_ARRAY, depth_.id());
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, size, size, layers, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
    gl::setDepthCompare(GL_TEXTURE_2D_ARRAY);
    glActiveTexture(GL_TEXTURE0);
    allocatedLayers_ = layers;
    ++stats.bufferUploads;
    if (glGetError() == GL_OUT_OF_MEMORY) {
      clear();
      return Error{"shadow maps: out of GPU memory for " + std::to_string(layers) + " layers of " + std::to_string(size) + "^2"};
    }
  }
  maps_ = std::move(maps);
  ++generation_;
  size_ = size;
  layerCount_ = layers;
  sceneVersion_ = scene.version;
  if (layers == 0) return okStatus();

  Result<gl::ShaderProgram*> prog = programs.get(gl::ShadowDepthProgram{}, stats.shaderBuilds);
  if (!prog) return Error{prog.error()};
  // See-through casters' programs, with and without maps.
  gl::ShaderProgram* seeThrough[2] = {nullptr, nullptr};
  for (const ShadowCaster& c : scene.casters) {
    if (!c.materials) continue;
    const bool maps = c.materials->hasMaps();
    Result<gl::ShaderProgram*> p = programs.get(gl::ShadowDepthProgram{true, maps}, stats.shaderBuilds);
    if (!p) return Error{p.error()};
    seeThrough[maps ? 1 : 0] = *p;
  }
  GLint target = 0, vp[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  glGetIntegerv(GL_VIEWPORT, vp);
  if (!fbo_.id()) fbo_ = gl::createFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  glViewport(0, 0, size, size);
  for (const LightMap& m : maps_) {
    if (m.firstLayer < 0) continue;
    for (int f = 0; f < (m.point ? 6 : 1); ++f) {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_.id(), 0, m.firstLayer + f);
      gl::apply(gl::pass::kClearTarget);
      glClearDepth(1.0);
      glClear(GL_DEPTH_BUFFER_BIT);
      gl::apply(gl::pass::kShadowDepth);
      for (const ShadowCaster& c : scene.casters) {
        gl::ShaderProgram& p = c.materials ? *seeThrough[c.materials->hasMaps() ? 1 : 0] : **prog;
        p.use();
        if (c.materials) c.materials->bind(p);
        p.set("uLightViewProjection", m.viewProjection[size_t(f)] * c.transform);
        c.mesh->drawAll();
        ++stats.drawCalls;
      }
    }
  }
  ++stats.shadowMapRenders;
  gl::apply(gl::pass::kBackground);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(vp[0], vp[1], vp[2], vp[3]);
  return okStatus();
}

void ShadowMaps::bind(gl::ShaderProgram& p, const glm::mat4& view) const {
  if (layerCount_ == 0) return;
  const glm::mat4 toModel = glm::inverse(view);
  const int n = static_cast<int>(maps_.size());
  std::vector<glm::mat4> matrices(static_cast<size_t>(layerCount_));
  std::vector<int> first(static_cast<size_t>(n)), point(static_cast<size_t>(n)), perspective(static_cast<size_t>(n));
  std::vector<float> texel(static_cast<size_t>(n));
  std::vector<glm::vec3> lightEye(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const LightMap& m = maps_[static_cast<size_t>(i)];
    first[size_t(i)] = m.firstLayer;
    point[size_t(i)] = m.point ? 1 : 0;
    perspective[size_t(i)] = m.perspective ? 1 : 0;
    texel[size_t(i)] = m.texelSize;
    lightEye[size_t(i)] = glm::vec3(view * glm::vec4(m.positionModel, 1.0f));
    if (m.firstLayer < 0) continue;
    for (int f = 0; f < (m.point ? 6 : 1); ++f) matrices[size_t(m.firstLayer + f)] = m.viewProjection[size_t(f)] * toModel;
  }
  gl::bindTexture(kShadowMapsUnit, GL_TEXTURE_2D_ARRAY, depth_.id());
  p.set("uShadowMaps", gl::unitIndex(kShadowMapsUnit));
  p.setArray("uShadowMatrix", matrices.data(), layerCount_);
  p.setArray("uShadowLayer", first.data(), n);
  p.setArray("uShadowPoint", point.data(), n);
  p.setArray("uShadowPerspective", perspective.data(), n);
  p.setArray("uShadowTexelSize", texel.data(), n);
  p.setArray("uShadowLightPosition", lightEye.data(), n);
  p.set("uEyeToModel", glm::mat3(toModel));
  p.set("uShadowTexel", 1.0f / float(size_));
}

}  // namespace npr
