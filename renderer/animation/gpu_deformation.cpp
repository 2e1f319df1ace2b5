// Posing on the GPU (see gpu_deformation.h).
#include "renderer/animation/gpu_deformation.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "renderer/programs/program_variants.h"

namespace npr {
namespace {

constexpr GLuint kGroup = 64;  // deform.comp's local_size_x

std::vector<std::size_t> activeTargets(const std::vector<float>& weights, std::size_t targets) {
  std::vector<std::size_t> active;
  for (std::size_t t = 0; t < targets && t < weights.size(); ++t)
    if (weights[t] != 0.0f && std::isfinite(weights[t])) active.push_back(t);
  return active;
}

void bindStorage(GLuint binding, GLuint buffer) { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer); }

}  // namespace

bool gpuDeformationSupported() {
  return epoxy_gl_version() >= 43 || (epoxy_has_gl_extension("GL_ARB_compute_shader") && epoxy_has_gl_extension("GL_ARB_shader_storage_buffer_object"));
}

bool GpuDeformation::fits(const std::vector<float>& weights) {
  return activeTargets(weights, weights.size()).size() <= static_cast<std::size_t>(gl::DeformProgram::kMaxActiveTargets);
}

void GpuDeformation::clear() {
  skin_.reset();
  joints_.reset();
  targets_.reset();
  restDirections_.reset();
  targetExtent_.clear();
  jointCapacity_ = jointCount_ = 0;
  uploaded_ = false;
}

void GpuDeformation::upload(const Mesh& rest, FrameStats& stats) {
  const MeshDeformation& d = rest.deformation;
  const std::size_t nv = rest.positions.size();
  if (d.skinned() && d.joints.size() == nv && d.weights.size() == nv) {
    std::vector<std::uint32_t> words(6 * nv);
    for (std::size_t i = 0; i < nv; ++i) {
      const glm::u16vec4& j = d.joints[i];
      words[6 * i] = std::uint32_t(j.x) | std::uint32_t(j.y) << 16;
      words[6 * i + 1] = std::uint32_t(j.z) | std::uint32_t(j.w) << 16;
      std::memcpy(&words[6 * i + 2], &d.weights[i], sizeof(glm::vec4));
    }
    skin_ = gl::createBuffer();
    gl::uploadBuffer(skin_, words.data(), words.size() * sizeof(std::uint32_t), GL_STATIC_DRAW);
    stats.bufferUploads += 1;
  }
  targetExtent_.assign(d.targets(), 0.0f);
  if (d.targets() > 0) {
    std::vector<float> deltas(d.targets() * nv * 6, 0.0f);
    for (std::size_t t = 0; t < d.targets(); ++t) {
      const bool normals = d.targetNormals.size() > t && d.targetNormals[t].size() == nv;
      if (d.targetPositions[t].size() != nv) continue;
      float extent = 0.0f;
      for (std::size_t i = 0; i < nv; ++i) {
        float* out = &deltas[(t * nv + i) * 6];
        const glm::vec3 p = d.targetPositions[t][i], n = normals ? d.targetNormals[t][i] : glm::vec3(0.0f);
        out[0] = p.x, out[1] = p.y, out[2] = p.z, out[3] = n.x, out[4] = n.y, out[5] = n.z;
        extent = std::max(extent, glm::length(p));
      }
      targetExtent_[t] = extent;
    }
    targets_ = gl::createBuffer();
    gl::uploadBuffer(targets_, deltas.data(), deltas.size() * sizeof(float), GL_STATIC_DRAW);
    stats.bufferUploads += 1;
  }
  uploaded_ = true;
}

Status GpuDeformation::pose(const Mesh& rest, const GpuMesh& gpu, const std::vector<glm::mat4>& joints, const std::vector<float>& weights,
                            gl::ProgramCache& programs, FrameStats& stats) {
  const GpuMesh::PoseStreams s = gpu.poseStreams();
  if (!s.restPositions || !s.positions || s.vertices != rest.positions.size()) return Error{"the mesh on the GPU has no rest pose to deform"};
  if (!uploaded_) upload(rest, stats);
  const MeshDeformation& d = rest.deformation;
  const std::vector<std::size_t> active = activeTargets(weights, d.targets());
  if (active.size() > static_cast<std::size_t>(gl::DeformProgram::kMaxActiveTargets))
    return Error{std::to_string(active.size()) + " morph targets with a weight: a pose on the GPU takes at most " +
                 std::to_string(gl::DeformProgram::kMaxActiveTargets)};
  gl::DeformProgram variant;
  variant.skin = skin_.id() != 0 && !joints.empty();
  variant.morph = !active.empty() && targets_.id() != 0;
  Result<gl::ShaderProgram*> program = programs.get(variant, stats.shaderBuilds);
  if (!program) return Error{program.error()};
  gl::ShaderProgram& p = **program;
  p.use();
  p.set("uVertexCount", static_cast<unsigned>(s.vertices));
  bindStorage(0, s.restPositions);
  bindStorage(1, s.restNormals);
  bindStorage(2, s.positions);
  bindStorage(3, s.normals);
  if (variant.skin) {
    if (!joints_.id() || joints.size() > jointCapacity_) {
      joints_ = gl::createBuffer();
      gl::uploadBuffer(joints_, joints.data(), joints.size() * sizeof(glm::mat4), GL_DYNAMIC_DRAW);
      jointCapacity_ = joints.size();
    } else {
      gl::updateBuffer(joints_, joints.data(), joints.size() * sizeof(glm::mat4));
    }
    stats.bufferUploads += 1;
    jointCount_ = joints.size();
    p.set("uJointCount", static_cast<unsigned>(jointCount_));
    bindStorage(4, skin_.id());
    bindStorage(5, joints_.id());
  }
  if (variant.morph) {
    std::vector<int> index;
    std::vector<float> weight;
    for (std::size_t t : active) {
      index.push_back(static_cast<int>(t));
      weight.push_back(weights[t]);
    }
    p.set("uActiveTargets", static_cast<int>(active.size()));
    p.setArray("uTarget", index.data(), static_cast<int>(index.size()));
    p.setArray("uTargetWeight", weight.data(), static_cast<int>(weight.size()));
    bindStorage(6, targets_.id());
  }
  glDispatchCompute(static_cast<GLuint>((s.vertices + kGroup - 1) / kGroup), 1, 1);
  // The next passes read the buffers as vertex attributes (and the stencil path's buffers as storage).
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  for (GLuint b = 0; b <= 6; ++b) bindStorage(b, 0);
  stats.gpuPoses += 1;
  return okStatus();
}

Status GpuDeformation::poseDirections(const Mesh& rest, const std::vector<glm::vec3>& restDirections, const GpuMesh& gpu,
                                      gl::ProgramCache& programs, FrameStats& stats) {
  const GpuMesh::PoseStreams s = gpu.poseStreams();
  if (!s.directions || restDirections.size() != s.vertices || !skin_.id() || !joints_.id() || !rest.deformation.skinned()) return okStatus();
  if (!restDirections_.id()) {
    restDirections_ = gl::createBuffer();
    gl::uploadBuffer(restDirections_, restDirections.data(), restDirections.size() * sizeof(glm::vec3), GL_STATIC_DRAW);
    stats.bufferUploads += 1;
  }
  gl::DeformProgram variant;
  variant.skin = true;
  variant.vectors = true;
  Result<gl::ShaderProgram*> program = programs.get(variant, stats.shaderBuilds);
  if (!program) return Error{program.error()};
  gl::ShaderProgram& p = **program;
  p.use();
  p.set("uVertexCount", static_cast<unsigned>(s.vertices));
  p.set("uJointCount", static_cast<unsigned>(jointCount_));
  bindStorage(0, restDirections_.id());
  bindStorage(2, s.directions);
  bindStorage(4, skin_.id());
  bindStorage(5, joints_.id());
  glDispatchCompute(static_cast<GLuint>((s.vertices + kGroup - 1) / kGroup), 1, 1);
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  for (GLuint b : {0u, 2u, 4u, 5u}) bindStorage(b, 0);
  return okStatus();
}

float GpuDeformation::radiusBound(const Mesh& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights) {
  float morphed = rest.radius;
  for (std::size_t t : activeTargets(weights, std::min(targetExtent_.size(), rest.deformation.targets())))
    morphed += std::fabs(weights[t]) * targetExtent_[t];
  float bound = morphed;  // a vertex without weights stays where the morph put it
  if (rest.deformation.skinned())
    for (const glm::mat4& m : joints) {
      // |A p + t| <= |t| + ||A||_F |p|
      const glm::mat3 a(m);
      const float frobenius = std::sqrt(glm::dot(a[0], a[0]) + glm::dot(a[1], a[1]) + glm::dot(a[2], a[2]));
      bound = std::max(bound, glm::length(glm::vec3(m[3])) + frobenius * morphed);
    }
  return std::isfinite(bound) && bound > 0.0f ? bound : rest.radius;
}

}  // namespace npr
