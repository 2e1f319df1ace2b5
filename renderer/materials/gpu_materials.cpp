// The mesh's appearance on the GPU (see gpu_materials.h).
#include "renderer/materials/gpu_materials.h"

#include <algorithm>
#include <cstring>

#include "renderer/core/image_io.h"
#include "renderer/gl/texture_units.h"
#include "renderer/materials/mesh_materials.h"

namespace npr {
namespace {
// This file's samplers' texture units (gl/texture_units.h).
const gl::TextureUnit kMaterialMapsUnit = gl::claimTextureUnit();  // their diffuse maps (GL_TEXTURE_2D_ARRAY)
const gl::TextureUnit kMaterialTableUnit = gl::claimTextureUnit();  // the mesh's materials (GL_TEXTURE_BUFFER)
}  // namespace
namespace {

// Maps share one array: each is resized to the largest map's size, at most this a side.
constexpr int kMaxMapSide = 1024;

gl::Texture bufferTexture(const gl::Buffer& buffer, GLenum format, gl::TextureUnit unit) {
  gl::Texture t = gl::createTexture();
  gl::bindTexture(unit, GL_TEXTURE_BUFFER, t.id());
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(gl::unitIndex(unit)));
  glTexBuffer(GL_TEXTURE_BUFFER, format, buffer.id());
  glActiveTexture(GL_TEXTURE0);
  return t;
}

// A material's coverage as its row's top byte (shaders/material.glsl decodes it): 0 opaque;
// 1..126 a mask's cutoff on the map's alpha, (code - 1) / 125, with the opacity folded in;
// 127 a mask never reached; 128..255 a blend's opacity, (code - 128) / 127.
std::uint32_t coverageCode(const MeshMaterial& m) {
  const float opacity = std::clamp(m.opacity, 0.0f, 1.0f);
  switch (m.alpha) {
    case MeshMaterial::Alpha::Opaque: return 0;
    case MeshMaterial::Alpha::Mask: {
      // alpha = opacity x map >= cutoff  <=>  map >= cutoff / opacity
      const float cutoff = std::clamp(m.alphaCutoff, 0.0f, 1.0f);
      if (cutoff <= 0.0f) return 1;
      if (opacity <= 0.0f || cutoff / opacity > 1.0f) return 127;
      return 1u + static_cast<std::uint32_t>(cutoff / opacity * 125.0f + 0.5f);
    }
    case MeshMaterial::Alpha::Blend: return 128u + static_cast<std::uint32_t>(opacity * 127.0f + 0.5f);
  }
  return 0;
}

}  // namespace

void GpuMaterials::clear() {
  active_ = false;
  coverage_ = false;
  tableBuffer_.reset();
  table_.reset();
  maps_.reset();
  mapSide_ = 0;
  rows_.clear();
}

void GpuMaterials::upload(const Mesh& mesh) {
  clear();
  if (!mesh.hasAppearance()) return;
  active_ = true;
  coverage_ = mesh.seeThrough;
  tableBuffer_ = gl::createBuffer();
  const std::size_t rows = std::max<std::size_t>(mesh.materials.size(), 1);
  gl::uploadBuffer(tableBuffer_, nullptr, rows * sizeof(glm::uvec4), GL_DYNAMIC_DRAW);
  table_ = bufferTexture(tableBuffer_, GL_RGBA32UI, kMaterialTableUnit);
  if (!mesh.textures.empty() && !mesh.texcoords.empty()) uploadMaps(mesh);
  // A see-through mesh's coverage is read by passes that may run before the frame's update()
  // (the shadow maps, the geometry pass): its rows are written now, with the default lighting
  // state's colours until then (coverage does not depend on them).
  if (coverage_) {
    FrameStats unused;
    update(mesh, LightingState{}, unused);
  }
}

void GpuMaterials::uploadMaps(const Mesh& mesh) {
  int side = 1;
  for (const MeshTexture& t : mesh.textures) side = std::max({side, t.image.width, t.image.height});
  mapSide_ = std::min(side, kMaxMapSide);
  maps_ = gl::createTexture();
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(gl::unitIndex(kMaterialMapsUnit)));
  glBindTexture(GL_TEXTURE_2D_ARRAY, maps_.id());
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, mapSide_, mapSide_, static_cast<GLsizei>(mesh.textures.size()), 0, GL_RGBA,
               GL_UNSIGNED_BYTE, nullptr);
  std::vector<std::uint8_t> flipped;
  for (std::size_t i = 0; i < mesh.textures.size(); ++i) {
    const ImageRGBA8* img = &mesh.textures[i].image;
    Result<ImageRGBA8> resized = Error{""};
    if (img->width != mapSide_ || img->height != mapSide_) {
      resized = resizeImage(*img, mapSide_, mapSide_);
      if (!resized) continue;  // left black; cannot happen for a decoded image
      img = &*resized;
    }
    // Image rows are top first; texture coordinates count v from the bottom.
    const std::size_t row = static_cast<std::size_t>(img->width) * 4;
    flipped.resize(img->pixels.size());
    for (int y = 0; y < img->height; ++y)
      std::memcpy(&flipped[static_cast<std::size_t>(img->height - 1 - y) * row], &img->pixels[static_cast<std::size_t>(y) * row], row);
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, static_cast<GLint>(i), img->width, img->height, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                    flipped.data());
  }
  glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
  // Bilinear within the nearest level: trilinear's second level cost llvmpipe about 8% of the
  // pixel path's frame on the 871K-triangle mesh with 4 of 16 materials mapped.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glActiveTexture(GL_TEXTURE0);

}

void GpuMaterials::update(const Mesh& mesh, const LightingState& lighting, FrameStats& stats) {
  if (!active_) return;
  const std::vector<Material> mats = glMaterials(mesh, lighting);
  auto colour = [](const glm::vec4& c) {
    const glm::uvec3 q(glm::clamp(glm::vec3(c), 0.0f, 1.0f) * 255.0f + 0.5f);
    return q.r | (q.g << 8) | (q.b << 16);
  };
  std::vector<glm::uvec4> rows;
  rows.reserve(mats.size());
  for (std::size_t i = 0; i < mats.size(); ++i) {
    const Material& m = mats[i];
    const int map = i < mesh.materials.size() && hasMaps() ? mesh.materials[i].diffuseMap : -1;
    // Shininess (0..128) in 1/512ths: 16 bits split over the diffuse and specular words.
    const std::uint32_t shininess = static_cast<std::uint32_t>(std::clamp(m.shininess, 0.0f, 127.99f) * 512.0f + 0.5f);
    rows.push_back(glm::uvec4(colour(m.ambient) | (static_cast<std::uint32_t>(map + 1) << 24), colour(m.diffuse) | ((shininess >> 8) << 24),
                              colour(m.specular) | ((shininess & 255u) << 24),
                              colour(m.emission) | (i < mesh.materials.size() ? coverageCode(mesh.materials[i]) << 24 : 0u)));
  }
  if (rows == rows_) return;
  rows_ = std::move(rows);
  glBindBuffer(GL_TEXTURE_BUFFER, tableBuffer_.id());
  glBufferSubData(GL_TEXTURE_BUFFER, 0, static_cast<GLsizeiptr>(rows_.size() * sizeof(glm::uvec4)), rows_.data());
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
  ++stats.bufferUploads;
}

bool GpuMaterials::mapped(std::size_t material) const { return material < rows_.size() && (rows_[material].x >> 24) > 0; }

void GpuMaterials::setMaterial(gl::ShaderProgram& p, std::size_t material) const {
  const glm::uvec4 row = material < rows_.size() ? rows_[material] : (rows_.empty() ? glm::uvec4(0) : rows_[0]);
  // As shaders/material.glsl unpacks a row.
  auto colour = [](std::uint32_t v) { return glm::vec3(float(v & 255u), float((v >> 8) & 255u), float((v >> 16) & 255u)) / 255.0f; };
  const glm::vec3 colours[4] = {colour(row.x), colour(row.y), colour(row.z), colour(row.w)};
  p.set("uMaterialColours[0]", colours[0]);
  p.set("uMaterialColours[1]", colours[1]);
  p.set("uMaterialColours[2]", colours[2]);
  p.set("uMaterialColours[3]", colours[3]);
  p.set("uMaterialShininess", float(((row.y >> 24) << 8) | (row.z >> 24)) / 512.0f);
  p.set("uMaterialMap", float(row.x >> 24) - 1.0f);
  if (coverage_) p.set("uMaterialCoverage", float(row.w >> 24));
}

void GpuMaterials::bind(gl::ShaderProgram& p) const {
  gl::bindTexture(kMaterialTableUnit, GL_TEXTURE_BUFFER, table_.id());
  p.set("uMaterialTable", gl::unitIndex(kMaterialTableUnit));
  if (!hasMaps()) return;
  gl::bindTexture(kMaterialMapsUnit, GL_TEXTURE_2D_ARRAY, maps_.id());
  p.set("uMaterialMaps", gl::unitIndex(kMaterialMapsUnit));
}

}  // namespace npr
