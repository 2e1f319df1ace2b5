// Ray-cast shadow reference (see shadow_reference.h).
#include "support/shadow_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace npr::test {
namespace {

// Moller-Trumbore: does the ray o + t d (t > 0) cross the triangle?
bool hits(const glm::vec3& o, const glm::vec3& d, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
  const float det = glm::dot(e1, p);
  if (std::fabs(det) < 1e-12f) return false;
  const float inv = 1.0f / det;
  const glm::vec3 s = o - a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return false;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(d, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return false;
  return glm::dot(e2, q) * inv > 1e-5f;
}

// The triangles binned by where they lie across the light: a ray toward the light from p can
// only cross triangles whose projection onto the plane across the light covers p's. Each
// triangle goes into every cell its projected bounding box touches, so no crossing is missed;
// the brute-force loop over every triangle took 20 s of the sanitizer build's test time.
class LightGrid {
 public:
  LightGrid(const Mesh& mesh, const glm::vec3& toLight) {
    u_ = glm::normalize(glm::cross(std::fabs(toLight.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), toLight));
    v_ = glm::cross(toLight, u_);
    const std::size_t n = mesh.triangleCount();
    lo_ = glm::vec2(std::numeric_limits<float>::infinity());
    glm::vec2 hi(-std::numeric_limits<float>::infinity());
    for (const glm::vec3& p : mesh.positions) lo_ = glm::min(lo_, across(p)), hi = glm::max(hi, across(p));
    cells_ = std::max(1, int(std::sqrt(double(n))));
    size_ = glm::max((hi - lo_) / float(cells_), glm::vec2(1e-6f));
    bins_.assign(std::size_t(cells_) * cells_, {});
    for (std::size_t t = 0; t < n; ++t) {
      glm::vec2 a(std::numeric_limits<float>::infinity()), b(-std::numeric_limits<float>::infinity());
      for (int k = 0; k < 3; ++k) {
        const glm::vec2 q = across(mesh.positions[mesh.indices[t * 3 + k]]);
        a = glm::min(a, q), b = glm::max(b, q);
      }
      const glm::ivec2 c0 = cell(a), c1 = cell(b);
      for (int y = c0.y; y <= c1.y; ++y)
        for (int x = c0.x; x <= c1.x; ++x) bins_[std::size_t(y) * cells_ + x].push_back(std::uint32_t(t));
    }
  }
  // The triangles a ray toward the light from p may cross (none where p lies outside them all).
  const std::vector<std::uint32_t>& candidates(const glm::vec3& p) const {
    static const std::vector<std::uint32_t> none;
    const glm::vec2 q = (across(p) - lo_) / size_;
    if (!(q.x >= 0.0f && q.y >= 0.0f && q.x <= float(cells_) && q.y <= float(cells_))) return none;
    const glm::ivec2 c = cell(across(p));
    return bins_[std::size_t(c.y) * cells_ + c.x];
  }

 private:
  glm::vec2 across(const glm::vec3& p) const { return {glm::dot(p, u_), glm::dot(p, v_)}; }
  glm::ivec2 cell(const glm::vec2& q) const { return glm::clamp(glm::ivec2(glm::floor((q - lo_) / size_)), glm::ivec2(0), glm::ivec2(cells_ - 1)); }
  glm::vec3 u_{0.0f}, v_{0.0f};
  glm::vec2 lo_{0.0f}, size_{1.0f};
  int cells_ = 1;
  std::vector<std::vector<std::uint32_t>> bins_;
};

float luminance(const std::uint8_t* p) { return (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f; }

}  // namespace

ShadowAgreement compareShadows(const Mesh& mesh, const glm::vec3& toLight, const CameraMatrices& camera, const ImageRGBA32F& pos,
                               const ImageRGBA32F& nrm, const ImageRGBA8& lit, const ImageRGBA8& shadowed, int band) {
  const int w = pos.width, h = pos.height;
  const glm::mat4 toModel = glm::inverse(camera.view);
  const glm::mat3 toModel3(toModel);
  // -1: not compared (uncovered or facing away), 0 lit, 1 shadowed; by the reference.
  std::vector<int> reference(std::size_t(w) * h, -1);
  const LightGrid grid(mesh, toLight);
  for (int i = 0; i < w * h; ++i) {
    if (pos.pixels[size_t(i) * 4 + 3] == 0.0f) continue;
    const glm::vec3 p = glm::vec3(toModel * glm::vec4(pos.pixels[size_t(i) * 4], pos.pixels[size_t(i) * 4 + 1], pos.pixels[size_t(i) * 4 + 2], 1.0f));
    glm::vec3 n = toModel3 * glm::vec3(nrm.pixels[size_t(i) * 4], nrm.pixels[size_t(i) * 4 + 1], nrm.pixels[size_t(i) * 4 + 2]);
    const float len = glm::length(n);
    if (!(len > 0.0f)) continue;
    n /= len;
    if (glm::dot(n, toLight) < 0.3f) continue;  // only where the light's diffuse term is clear
    bool blocked = false;
    const glm::vec3 o = p + n * 1e-3f;
    for (std::size_t k = 0; k < grid.candidates(o).size() && !blocked; ++k) {
      const std::size_t t = grid.candidates(o)[k];
      blocked = hits(o, toLight, mesh.positions[mesh.indices[t * 3]], mesh.positions[mesh.indices[t * 3 + 1]], mesh.positions[mesh.indices[t * 3 + 2]]);
    }
    reference[size_t(i)] = blocked ? 1 : 0;
  }
  ShadowAgreement out;
  std::size_t agree = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int r = reference[size_t(y) * w + x];
      if (r < 0) continue;
      bool nearEdge = false;
      for (int dy = -band; dy <= band && !nearEdge; ++dy)
        for (int dx = -band; dx <= band && !nearEdge; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
          const int q = reference[size_t(yy) * w + xx];
          nearEdge = q >= 0 && q != r;
        }
      if (nearEdge) continue;
      const std::size_t i = (size_t(y) * w + x) * 4;
      const bool drawnShadowed = luminance(&lit.pixels[i]) - luminance(&shadowed.pixels[i]) > 0.1f;
      ++out.compared;
      out.shadowed += r == 1;
      agree += (r == 1) == drawnShadowed;
    }
  out.agreement = out.compared ? double(agree) / double(out.compared) : 0.0;
  return out;
}

}  // namespace npr::test
