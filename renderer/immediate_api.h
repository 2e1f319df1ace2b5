// The original palette renderer's own interface, kept for code written against it: OpenGL-
// shaped state calls (Lightfv, Materialfv, LightModelfv, Enable/Disable), ColorMatchMode and
// IntensityRangeScale, and immediate drawing with Begin(), RenderTriangle(tri), End().
// Triangles are collected between Begin and End and drawn by the same Renderer as the
// retained mesh path (by default with the original stencil-bucket algorithm). As in OpenGL, a
// Materialfv between RenderTriangle calls applies to the triangles that follow it.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"
#include "renderer/renderer.h"

namespace npr {

struct Triangle {
  std::array<glm::vec3, 3> v;  // counter-clockwise when front-facing
};

// Flat arrays for unconnected triangles (face normals as vertex normals): what End() draws.
Mesh meshFromTriangles(const std::vector<Triangle>& triangles);

class PaletteRenderer {
 public:
  explicit PaletteRenderer(Renderer& renderer) : renderer_(renderer) {}

  Status Lightfv(GLenum light, GLenum pname, const float* v) { return renderer_.lighting().Lightfv(light, pname, v); }
  Status Lightf(GLenum light, GLenum pname, float v) { return renderer_.lighting().Lightf(light, pname, v); }
  Status Materialfv(GLenum face, GLenum pname, const float* v) { return renderer_.lighting().Materialfv(face, pname, v); }
  Status Materialf(GLenum face, GLenum pname, float v) { return renderer_.lighting().Materialf(face, pname, v); }
  Status LightModelfv(GLenum pname, const float* v) { return renderer_.lighting().LightModelfv(pname, v); }
  Status LightModeli(GLenum pname, int v) { return renderer_.lighting().LightModeli(pname, v); }
  Status Enable(GLenum cap) { return renderer_.lighting().Enable(cap); }
  Status Disable(GLenum cap) { return renderer_.lighting().Disable(cap); }
  void ColorMatchMode(MatchMode mode) { settings_.match = mode; }
  Status IntensityRangeScale(float scale);
  void RenderPathMode(RenderPath path) { settings_.path = path; }

  void Begin();
  void RenderTriangle(const Triangle& tri);
  // Draws the collected triangles into the bound framebuffer's viewport.
  Status End(const CameraMatrices& camera, const glm::ivec4& viewport);

  const RenderSettings& settings() const { return settings_; }

 private:
  Renderer& renderer_;
  RenderSettings settings_ = [] { RenderSettings s; s.path = RenderPath::Stencil; return s; }();
  std::vector<Triangle> pending_;
  std::vector<Material> materials_;                // front materials current during Begin..End
  std::vector<std::uint16_t> triangleMaterials_;   // per pending triangle, into materials_
  Mesh mesh_;
  bool begun_ = false;
};

}  // namespace npr
