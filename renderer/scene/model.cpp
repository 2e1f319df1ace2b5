// A model of the scene and its derived caches (see model.h).
#include "renderer/scene/model.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/animation/deformation.h"
#include "renderer/mesh/mesh_subset.h"

namespace npr {

void Model::adopt(const Mesh& mesh) {
  rest_ = &mesh;
  posed_.reset();
  poseJoints_.clear();
  poseWeights_.clear();
  posedDirections_.clear();
  gpuPose_.clear();
  gpuPending_ = cpuStale_ = false;
  if (!mesh.deformation.empty() && !mesh.indices.empty()) {
    // A copy whose positions and normals are rewritten in place: everything derived from the
    // drawn mesh is derived once, from it, and only moves with the pose.
    posed_ = std::make_unique<Mesh>(mesh);
  }
  mesh_ = posed_ ? posed_.get() : &mesh;
}

Model::Model(const Mesh& mesh, const glm::mat4& transform, FrameStats& stats, bool appearance)
    : mesh_(&mesh), rest_(&mesh), transform_(transform) {
  adopt(mesh);
  triangles_.setMesh(mesh_);
  lines_.setMesh(mesh_);
  strokes_.setMesh(mesh_, rest_);
  patterns_.setMesh(mesh_);
  gpu_.upload(*mesh_);
  stats.bufferUploads += 1;
  if (!appearance) return;
  materials_.upload(mesh);
  stats.bufferUploads += 2;
}

void Model::reset(const Mesh& mesh, const glm::mat4& transform, FrameStats& stats) {
  adopt(mesh);
  transform_ = transform;
  palette_.reset();
  field_.reset();
  occlusion_.reset();
  parts_.clear();
  triangles_.setMesh(mesh_);
  lines_.setMesh(mesh_);
  strokes_.setMesh(mesh_, rest_);
  patterns_.setMesh(mesh_);
  gpu_.upload(*mesh_);
  materials_.upload(mesh);
  stats.bufferUploads += 3;
}

void Model::deform(const std::vector<glm::mat4>& joints, const std::vector<float>& weights) {
  if (!posed_) return;
  poseJoints_ = joints;
  poseWeights_ = weights;
  gpuPending_ = cpuStale_ = true;
}

Status Model::applyPose(bool onGpu, bool onCpu, gl::ProgramCache& programs, FrameStats& stats) {
  if (!posed_ || (!gpuPending_ && !cpuStale_)) return okStatus();
  if (onGpu && (!gpuDeformationSupported() || !GpuDeformation::fits(poseWeights_))) {
    onGpu = false;
    onCpu = true;
  }
  if (!onGpu) {
    if (gpuPending_ || cpuStale_) poseOnCpu(true, stats);
    gpuPending_ = false;
    return okStatus();
  }
  if (onCpu && cpuStale_) poseOnCpu(false, stats);
  if (!gpuPending_) return okStatus();
  if (Status st = gpuPose_.pose(*rest_, gpu_, poseJoints_, poseWeights_, programs, stats); !st) return st;
  if (field_)
    if (Status st = gpuPose_.poseDirections(*rest_, field_->directions, gpu_, programs, stats); !st) return st;
  gpuPending_ = false;
  // The scene's bounds (shadow maps, a depth axis) while the CPU has not made the pose.
  if (cpuStale_) posed_->radius = gpuPose_.radiusBound(*rest_, poseJoints_, poseWeights_);
  return okStatus();
}

void Model::poseOnCpu(bool upload, FrameStats& stats) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool field = field_ && field_->directions.size() == rest_->positions.size();
  deformMesh(*rest_, poseJoints_, poseWeights_, *posed_, field ? &field_->directions : nullptr, &posedDirections_);
  if (upload) {
    if (field) gpu_.uploadDirections(posedDirections_);
    gpu_.updateGeometry(*mesh_);
    stats.bufferUploads += 1;
  }
  triangles_.geometryChanged();
  lines_.geometryChanged();
  strokes_.geometryChanged();
  // Parts read the model's vertices; their own faces' centroids and normals follow.
  for (auto& p : parts_) {
    copyFaceGeometry(*mesh_, p->faces);
    p->triangles.geometryChanged();
  }
  cpuStale_ = false;
  stats.cpuPoses += 1;
  stats.cpuPoseMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void Model::poseToneSamples(std::size_t stride) {
  if (!posed_ || !cpuStale_ || stride == 0) return;
  deformFaces(*rest_, poseJoints_, poseWeights_, *posed_, stride / 2, stride);
}

float Model::pixelsPerFrontTriangle(const CameraMatrices& placed, const glm::ivec4& viewport) const {
  const float frontTriangles = 0.5f * float(mesh_->indices.size() / 3);
  if (memberSpheres_.empty()) return projectedSphereArea(placed, mesh_->radius, viewport) / frontTriangles;
  float area = 0.0f;
  for (const glm::vec4& s : memberSpheres_)
    area += projectedSphereArea({placed.view * glm::translate(glm::mat4(1.0f), glm::vec3(s)), placed.projection}, s.w, viewport);
  return area / frontTriangles;
}

float Model::scale() const {
  float scale = 0.0f;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, glm::length(glm::vec3(transform_[c])));
  return scale;
}

float Model::sceneRadius() const { return mesh_->radius * scale(); }

const DirectionField& Model::directionField(FrameStats& stats) {
  if (!field_) {
    field_ = computeDirectionField(*rest_);
    ++stats.meshCachesBuilt;
    stats.cpuFieldMs = field_->ms;
    if (posed_ && rest_->deformation.skinned() && !poseJoints_.empty()) {
      // Computed on the rest mesh, drawn carried by the current pose.
      poseOnCpu(true, stats);
      gpuPending_ = false;
    } else {
      gpu_.uploadDirections(field_->directions);
    }
    for (auto& p : parts_) p->gpu.shareStreamsOf(gpu_);  // parts draw through the model's streams
    stats.bufferUploads += 1;
  }
  return *field_;
}

const std::vector<glm::vec3>& Model::surfaceDirections(FrameStats& stats) {
  const DirectionField& f = directionField(stats);
  return posed_ && posedDirections_.size() == f.directions.size() ? posedDirections_ : f.directions;
}

Status Model::startOcclusionBake() {
  if (occlusion_) return okStatus();
  Result<std::unique_ptr<OcclusionBake>> bake = OcclusionBake::start(*mesh_, gpu_);
  if (!bake) return Error{bake.error()};
  occlusion_ = std::move(*bake);
  return okStatus();
}

void Model::occlusionBaked(FrameStats& stats) {
  gpu_.uploadOcclusion(occlusion_->values());
  for (auto& p : parts_) p->gpu.shareStreamsOf(gpu_);  // parts draw through the model's streams
  stats.bufferUploads += 1;
}

void Model::uploadParts(const std::vector<PartKey>& keys, const std::vector<std::size_t>& partOf, FrameStats& stats) {
  for (std::size_t g = 0; g < keys.size(); ++g) {
    std::vector<char> keep(mesh_->triangleCount(), 0);
    bool any = false;
    for (std::size_t f = 0; f < keep.size(); ++f) {
      keep[f] = partOf[mesh_->faceMaterials[f]] == g;
      any = any || keep[f];
    }
    if (!any) continue;
    auto part = std::make_unique<Part>();
    part->palette = keys[g].first;
    part->detail = keys[g].second;
    part->faces = meshFaces(*mesh_, keep);
    // Only the part's index buffer is its own: it draws through the model's vertex streams
    // (the direction field and occlusion included, when the model has them).
    part->gpu.uploadPart(gpu_, part->faces.faces);
    part->triangles.setMesh(&part->faces.faces, mesh_);
    stats.bufferUploads += 1;
    parts_.push_back(std::move(part));
  }
}

}  // namespace npr
