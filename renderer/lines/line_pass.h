// Object-space feature lines drawn over any path: silhouettes, creases, boundaries and
// material lines from FeatureEdges, suggestive contours from SuggestiveContours, as
// screen-space quads of a fixed pixel width (core profiles have no wide lines), depth-tested
// against the model. Adjacency is built on first use per mesh; creases and boundaries are
// uploaded once per mesh and angle, silhouettes and suggestive contours when the eye moves.
#pragma once

#include <algorithm>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lines/feature_edges.h"
#include "renderer/lines/line_chains.h"
#include "renderer/lines/occlusion_layers.h"
#include "renderer/lines/stroke_textures.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/lines/suggestive_contours.h"
#include "renderer/mesh/mesh.h"
#include "renderer/settings/render_settings.h"

namespace npr {

// A buffer of ChainedLines (line_chains.h) and the part of it to draw.
struct LineRange {
  const gl::Buffer* buffer;
  std::size_t first, count;
};

// Materials past this index are never selected by a line set (lines.vert's mask).
inline constexpr int kMaxSelectableMaterials = 256;

// A file's point drawn with lines `width` pixels wide: its diameter in pixels (lines.vert's dots
// are drawn so; the SVG export writes them so).
inline float markDotDiameter(float width) { return std::max(2.5f * width, 3.0f); }

// How a group of lines is drawn: the line settings' own style for the kinds no set takes, or a
// line set's.
struct LineStyle {
  float width = 2.0f;                   // pixels
  glm::vec3 colours[kEdgeKinds]{};      // per EdgeKind
  bool visible = true, hidden = false;  // which parts
  glm::vec2 dash{0.0f};                 // the visible parts' dashes, pixels on and off (0: solid)
  glm::vec2 hiddenDash{6.0f, 4.0f};
  float hiddenWidthScale = 1.0f, hiddenInk = 1.0f;  // the hidden parts thinner and lighter
  bool sketchy = false, falloff = false;
  float taper = 0.0f;                   // pixels at each end of a stroke (0: blunt)
  std::string texture;                  // stretched along each stroke (stroke_textures.h); empty: none
  StrokeTexture textureBound;           // what `texture` names, once the feature has loaded it (id 0: none)
  // Width x (curvature / reference)^gain, within 1/4..4 (0: off); the reference is the mesh's
  // median curvature (FeatureEdges::medianCurvature), set where the style is drawn.
  float curvatureGain = 0.0f, curvatureReference = 1.0f;
  // colour=tone: lit with `lighting` at each line and drawn in the average colour of the entry
  // of `palette` its tone matches; the feature drawing it sets them (none: the set's colours).
  bool toneColour = false;
  const LightingState* lighting = nullptr;
  const GpuPalette* palette = nullptr;
  MatchMode match = MatchMode::Intensity;
  bool tonedNow() const { return toneColour && lighting && palette; }
  // Hidden parts drawn only where at most `occlusion` surfaces lie in front (0: all), read from
  // the layers the feature peeled for this level (null: all drawn).
  int occlusion = 0;
  const OcclusionLayers* layers = nullptr;
  bool limitsOcclusion() const { return hidden && occlusion > 0 && layers; }
  // A set selecting materials: the materials it takes, by index into the mesh's, as bits
  // (resolve() fills them from the set's names); lines on no such face are not drawn.
  const std::vector<std::string>* materialNames = nullptr;
  std::array<std::uint32_t, kMaxSelectableMaterials / 32> materialMask{};
  bool byMaterial() const { return materialNames != nullptr; }
  void resolveMaterials(const std::vector<MeshMaterial>& materials);
  std::uint8_t kinds = 0;               // bit EdgeKind: what it draws
  // The base style on the object named `object` (null: the scene's intersections).
  static LineStyle base(const LineSettings& ls, const std::string* object);
  static LineStyle of(const LineSet& set, const LineSettings& ls);
};
// Every style the settings draw with on the object named `object` (null: the scene's
// intersections), in drawing order: the base style first (when `lines` names a kind no set
// takes there), then the sets that apply there.
std::vector<LineStyle> lineStyles(const LineSettings& ls, const std::string* object);
// Layer `layer` of that order on `object`: -1 the base style, k the k-th set; none where it
// draws nothing there. A scene draws each layer on every object before the next.
std::optional<LineStyle> lineStyleLayer(const LineSettings& ls, int layer, const std::string* object);

// Draws `ranges` (lines in the space `placed` maps to the clip space) in `style`: the visible
// parts, then the hidden ones. Shared by each model's edges and the scene's intersection lines.
[[nodiscard]] Status drawLineRanges(const std::vector<LineRange>& ranges, const CameraMatrices& placed, const LineStyle& style,
                                    const glm::ivec4& viewport, const gl::VertexArray& vao, gl::ProgramCache& programs, FrameStats& stats);

class LinePass {
 public:
  // Forgets the previous mesh's lines (they are rebuilt on the next draw).
  void setMesh(const Mesh* mesh);
  // The mesh was deformed in place: the lines follow (their edges are not searched again).
  void geometryChanged();
  // Whether the next update with these settings builds the mesh's edges (buildEdges), which
  // takes no GL and may run on any thread, one per pass: a scene builds its objects' at once.
  bool needsEdges(const LineSettings& lines) const;
  void buildEdges();
  // Finds and uploads what the settings draw for this view (the static kinds once per mesh).
  void update(const CameraMatrices& camera, const LineSettings& lines, const glm::ivec4& viewport, FrameStats& stats);
  // Draws the lines of `style` found by the last update (a scene draws each style on every
  // model before the next: a later set lies over an earlier one on every object).
  [[nodiscard]] Status drawStyle(LineStyle style, const CameraMatrices& camera, const glm::ivec4& viewport, gl::ProgramCache& programs,
                                 FrameStats& stats);
  // The object-space lines `draw` shows for this camera and these settings (silhouettes,
  // creases, boundaries, material lines, suggestive contours, as enabled): what vector export
  // writes.
  std::vector<FeatureLine> lines(const CameraMatrices& camera, const LineSettings& lines);
  // Draws the file's own marks (Mesh::dots and segments: glTF points and lines) in `style`'s
  // silhouette colour and width, visible parts only: the segments chained into strokes, the
  // dots round, two and a half widths across (at least 3 pixels). Uploaded the first time.
  [[nodiscard]] Status drawMarks(LineStyle style, const CameraMatrices& camera, const glm::ivec4& viewport, gl::ProgramCache& programs,
                                 FrameStats& stats);

 private:
  void ensureBuffers();
  const Mesh* mesh_ = nullptr;
  std::unique_ptr<FeatureEdges> edges_;
  std::unique_ptr<SuggestiveContours> suggestive_;  // made when first drawn (it estimates the curvature)
  gl::VertexArray vao_;
  gl::Buffer staticLines_, silhouettes_, suggestiveLines_, marks_;
  std::size_t marksCount_ = 0;  // segments, then dots, in marks_ (0 until uploaded)
  // Each kind's edges chained into strokes; the silhouettes' and suggestive contours' parameters
  // carried from one view to the next.
  LineChains staticChains_, silhouetteChains_, suggestiveChains_;
  std::size_t staticCount_ = 0, creaseCount_ = 0, boundaryCount_ = 0, silhouetteCount_ = 0, suggestiveCount_ = 0;
  float uploadedCreaseAngle_ = -1.0f;
  glm::vec3 silhouetteEye_{NAN}, suggestiveEye_{NAN};
  float suggestiveThreshold_ = -1.0f;
};

}  // namespace npr
