// The palette renderer: draws a mesh with a palette along one of several paths that trade
// speed for accuracy. All paths light with the shared lighting model (lighting_model.h and
// shaders/lighting.glsl) and match with the shared PaletteMatcher; they differ only in where
// lighting is sampled and how the palette reaches the screen (always in screen space).
//
// The renderer draws into whatever framebuffer is bound (the window's, or an
// OffscreenTarget) and needs a current OpenGL 3.3+ core context. It never sees a window.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/palette_matcher.h"
#include "renderer/paths/path_table.h"
#include "renderer/core/result.h"
#include "renderer/shading/triangle_shading.h"

namespace npr {

// Lines drawn over any path (object-space feature edges; see feature_edges.h).
struct LineSettings {
  bool silhouettes = false, creases = false, boundaries = false;
  float creaseAngle = 60.0f;  // degrees
  float width = 2.0f;         // pixels
  glm::vec3 silhouetteColour{0.0f}, creaseColour{1.0f}, boundaryColour{0.15f, 0.1f, 0.05f};
  bool depthFalloff = false;
  bool sketchy = false;
  // Image space: Sobel on the depth and normal buffers, thresholded, drawn as a post-process.
  bool imageSpace = false;
  float imageThreshold = 0.4f;
  bool any() const { return silhouettes || creases || boundaries || imageSpace; }
};

struct RenderSettings {
  RenderPath path = RenderPath::Pixel;
  MatchMode match = MatchMode::Intensity;
  float rangeScale = 1.0f;
  std::vector<float> bands;  // cel band thresholds (see PaletteMatcher::create); empty: nearest level
  bool referenceGouraud = false;  // `reference` path: per-vertex instead of per-pixel lighting
  // Stencil path refinements over the original (off = the naive full-screen version):
  bool stencilScissor = true;     // bound each bucket's quads to its triangles' screen rectangle
  bool stencilSkipEmpty = true;   // draw nothing for buckets with no triangle
  bool drawBackground = true;
  // What the pixels hold: the image, or (for tests and the benchmark's references) the chosen
  // palette entry (entry / 255 in red; stencil draws as triangle), the selection as floats
  // (entry a, entry b, weight of b: what `smooth` blends), or interpolated eye-space position
  // (alpha -1 on back faces) or normal. Read the float outputs from a float target.
  enum class Output { Image, PaletteEntry, PaletteBlend, EyePosition, EyeNormal } output = Output::Image;
  LineSettings lines;
};

// What the last frame did: the counters are zero on frames where nothing they depend on
// changed (the benchmark and the overlay show them).
struct FrameStats {
  double cpuShadingMs = 0.0;   // per-triangle lighting, matching and bucketing
  double cpuFrameMs = 0.0;     // everything render() did on the CPU
  double gpuMs = -1.0;         // GPU time of the most recent frame whose timer query finished
  int nonEmptyBuckets = 0;
  int lightingRecomputes = 0;  // per-triangle shading runs
  int bufferUploads = 0;       // mesh, bucket, per-triangle entry and LUT uploads
  int shaderBuilds = 0;
  int lutBuilds = 0;
  int drawCalls = 0;
  int lines = 0;               // feature lines drawn
  double cpuLinesMs = 0.0;     // silhouette extraction
};

class Renderer {
 public:
  static Result<std::unique_ptr<Renderer>> create();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Uploads the mesh. The renderer keeps a pointer for per-triangle shading: call again
  // (or with nullptr) before the mesh is destroyed or replaced.
  void setMesh(const Mesh* mesh);
  // Uploads the palette; on failure the current one stays in place.
  Status setPalette(const Palette& palette);

  // The OpenGL-like lighting state (Lightfv, Materialfv, ...).
  LightingState& lighting() { return lighting_; }
  const LightingState& lighting() const { return lighting_; }

  // Draws one frame into the bound framebuffer's `viewport` (x, y, width, height).
  Status render(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport);
  // Reads finished GPU timer queries into stats().gpuMs (render() does this first). Call it
  // after the GPU work is finished to attribute a frame's time to that frame.
  void collectGpuTime();
  // A small screen-facing disc at `worldPosition` (the light marker).
  void drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour, float pixels,
                  const glm::ivec4& viewport);

  const FrameStats& stats() const { return stats_; }
  // The matcher of the last frame (for tests and the benchmark's accuracy reference).
  const PaletteMatcher* matcher() const { return matcher_ ? &*matcher_ : nullptr; }
  const TriangleShading& triangleShading() const { return shading_; }
  int paletteSize() const { return paletteSize_; }

 private:
  Renderer() = default;
  struct GpuPalette;
  Result<GLuint> program(const std::string& vertex, const std::string& fragment, std::vector<std::string> defines);
  Status ensureMatcher(const RenderSettings& s);
  void ensureTriangleShading(const glm::mat4& modelView, const CameraMatrices& camera, const RenderSettings& s,
                             const glm::ivec4& viewport);
  std::vector<std::string> paletteDefines(MatchMode mode) const;
  void bindPaletteTextures(GLuint program) const;
  void drawBackground();
  void drawBucket(int entry);
  Status renderStencil(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport);
  void setMeshUniforms(GLuint program, const CameraMatrices& camera);
  Status drawLines(const CameraMatrices& camera, const LineSettings& lines, const glm::ivec4& viewport);
  Status drawImageSpaceEdges(const CameraMatrices& camera, const LineSettings& lines, const glm::ivec4& viewport);

  LightingState lighting_;
  FrameStats stats_;

  // Mesh
  const Mesh* mesh_ = nullptr;
  unsigned meshGeneration_ = 0;
  gl::VertexArray vao_;
  gl::Buffer positions_, normals_, indices_, bucketIndices_;
  std::size_t triangleCount_ = 0;

  // Palette
  std::unique_ptr<GpuPalette> palette_;
  int paletteSize_ = 0;
  unsigned paletteGeneration_ = 0;
  std::vector<glm::vec3> averages_;

  // Matching
  std::optional<PaletteMatcher> matcher_;
  struct MatcherKey {
    unsigned palette = 0;
    MatchMode mode = MatchMode::Intensity;
    float scale = 0;
    std::vector<float> bands;
  } matcherKey_;
  unsigned matcherGeneration_ = 0;
  gl::Texture lutIndex_, lutBlend_, lut3D_;

  // Per-triangle shading cache
  TriangleShading shading_;
  struct ShadingKey {
    unsigned mesh = 0, matcher = 0;
    PreparedLighting<float> lighting;
    bool valid = false;
  } shadingKey_;
  bool bucketsUploaded_ = false;
  // The stencil path's scissor rectangles: vertices projected once per view, bounds once per
  // change of the buckets or the view.
  std::vector<glm::vec2> screenVertices_;
  glm::mat4 projectedViewProjection_{0.0f};
  glm::ivec2 projectedViewport_{0};
  unsigned projectedMesh_ = 0;
  bool boundsValid_ = false;

  // Feature lines: adjacency built on first use per mesh; creases and boundaries uploaded
  // once per mesh and angle, silhouettes when the eye moves.
  std::unique_ptr<class FeatureEdges> edges_;
  gl::VertexArray lineVao_;
  gl::Buffer staticLineBuffer_, silhouetteBuffer_;
  std::size_t staticLineCount_ = 0, silhouetteCount_ = 0;
  float uploadedCreaseAngle_ = -1.0f;
  glm::vec3 silhouetteEye_{NAN};
  // Image-space edges: normals and depth of the frame, at the viewport's size.
  gl::Framebuffer edgeFbo_;
  gl::Texture edgeNormals_, edgeDepth_;
  glm::ivec2 edgeSize_{0};

  // Programs, cached by variant: toggling features back and forth costs no rebuild.
  std::map<std::string, gl::Program> programs_;
  gl::VertexArray emptyVao_;
  static constexpr int kTimerSlots = 4;
  gl::Query timers_[kTimerSlots];
  int timerIndex_ = 0;
  bool timerPending_[kTimerSlots] = {false, false, false, false};
};

}  // namespace npr
