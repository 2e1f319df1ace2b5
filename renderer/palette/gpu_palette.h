// A palette on the GPU: its entries as one texture array (layers precomposited over the
// background where that is exact), the background image, and the matcher with its lookup
// tables for the current match mode, range scale and bands. Binds all of it for palette.glsl
// and says which palette variant a program must be compiled for, as the frame places the
// pattern (patterns/pattern_placement.h: the frame's, not the palette's).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/programs/program_variants.h"
#include "renderer/gl/shader_program.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/palette_matcher.h"
#include "renderer/patterns/pattern_placement.h"
#include "renderer/settings/render_settings.h"

namespace npr {

class GpuPalette {
 public:
  // Uploads the whole palette or fails with a message (too many layers or too large for this
  // GPU, out of GPU memory); nothing is half-made.
  [[nodiscard]] static Result<std::unique_ptr<GpuPalette>> upload(const Palette& palette);

  // Layers: every row's entries (palette.h); a palette without an axis has one row.
  int size() const { return static_cast<int>(layerSizes_.size()); }
  // A two-dimensional palette (palette.h): its rows, and the entries of each (what matching picks).
  int rows() const { return axis_.rows; }
  int columns() const { return columns_; }
  const PaletteAxis& axis() const { return axis_; }
  // The scene's bounding radius, the unit of a depth axis, for the frames drawn next.
  void setAxisScale(float sceneRadius);
  // Where a surface point (eye space) falls among the rows, in [0, rows - 1]: the per-triangle
  // paths' choice at each centroid; palette.glsl's setPaletteRow is the same per pixel.
  float rowPosition(const glm::vec3& eyePosition, const glm::vec3& eyeNormal, float detail = 0.0f) const;
  glm::vec2 axisMap() const { return axisMap_; }
  // Each entry's average colour (over the background), as the analysis measured it.
  const std::vector<glm::vec3>& averages() const { return averages_; }
  bool backgroundImage() const { return backgroundImage_; }
  glm::ivec2 layerSize(int entry) const { return layerSizes_[static_cast<size_t>(entry)]; }

  // Brings the matcher and its lookup tables up to date; rebuilt only when one of the three
  // changed (counted in stats.lutBuilds and stats.bufferUploads).
  // `toneTarget`: the automatic tone range's query span (palette_matcher.h), or none.
  // `slot`: a palette keeps one matcher per tone target in use; slot 0 is the scene's, and an
  // object fitted to its own tones (--tone-range per-object) draws with its own slot.
  [[nodiscard]] Status updateMatcher(MatchMode mode, float rangeScale, const std::vector<float>& bands, FrameStats& stats,
                                     std::optional<glm::vec2> toneTarget = std::nullopt, int slot = 0);
  // The slot matcher(), matcherId() and bind() use from now on; one never made falls back to 0.
  void useMatcher(int slot) const { active_ = slot > 0 && slot < int(slots_.size()) && slots_[size_t(slot)].matcher ? slot : 0; }
  // Null until updateMatcher succeeded once.
  const PaletteMatcher* matcher() const { return current().matcher ? &*current().matcher : nullptr; }
  // Unique across palettes, slots and rebuilds: what per-triangle results computed with it are keyed by.
  unsigned matcherId() const { return current().id; }

  bool layerSizesDiffer() const { return sizesDiffer_; }
  // Layers stored composited over the background (opaque; alpha then holds tone thresholds).
  bool precomposited() const { return precomposited_; }
  // Mapped lookups filter bilinearly in linear light (asked for, and the layers share a size).
  bool filtered(const PatternPlacement& at) const {
    return at.linearFilter && at.mapping() != gl::PatternMapping::Screen && !sizesDiffer_;
  }
  // The mip level a pattern drawn at `texelsPerPixel` reads: the nearest level (GL's
  // NEAREST_MIPMAP rule), clamped to the levels there are.
  int lodFor(float texelsPerPixel) const;

  // Whether lookups are turned: the frame orients the hatching and some entry has a dominant
  // direction (a stipple palette costs nothing under --orient).
  bool oriented(const PatternPlacement& at) const { return at.orient.source != OrientSource::None && anyOriented_; }
  // Whether some entry has a stroke direction (what an orientation would turn).
  bool hasOrientedEntries() const { return anyOriented_; }
  // Where mesh passes take the stroke angle from (None when not oriented).
  gl::StrokeSource strokeSource(const PatternPlacement& at) const;
  int orientBins(const PatternPlacement& at) const { return oriented(at) ? at.orient.bins : 0; }
  // Entry k's stroke direction in radians (below -10: none, left unturned).
  float entryAngle(int entry) const { return entryAngles_[static_cast<size_t>(entry)]; }

  // Crisp tone (palette/tone_thresholds.h): whether each layer's alpha holds the texel's
  // threshold, which the smooth path compares instead of blending (--tone-blend threshold); the
  // layers must be stored composited over their background (alpha unused), share a size and
  // nest. `toneThresholdNote()`: why not, when not.
  bool hasToneThresholds() const { return toneThresholds_; }
  const std::string& toneThresholdNote() const { return toneThresholdNote_; }

  // The variant of a program that draws this palette as the frame places it.
  gl::PaletteVariant variant(MatchMode mode, const PatternPlacement& at) const;
  // For programs that only match (read no texels of the layers): no mapping, filter or turns,
  // whatever the frame's placement.
  gl::PaletteVariant matchingVariant(MatchMode mode) const { return variant(mode, PatternPlacement{}); }
  // The stroke source's uniforms (orientation.glsl): fixed angle, light, viewport size.
  void bindStrokeSource(gl::ShaderProgram& program, const PatternPlacement& at) const;
  // The turned lookups' uniforms (steps, the frame's turn), for palette.glsl and layer quads.
  void bindOrientation(gl::ShaderProgram& program, const PatternPlacement& at) const;
  // The pattern's uniforms (pattern.glsl), when mapped.
  void bindPattern(gl::ShaderProgram& program, const PatternPlacement& at) const;
  // Everything palette.glsl samples: layers, background, lookup tables, and their uniforms;
  // with `turned`, for a program compiled with this palette's orientation (orientBins()).
  void bind(gl::ShaderProgram& program, const PatternPlacement& at, bool turned) const;
  // What a matchingVariant() program reads.
  void bindMatching(gl::ShaderProgram& program) const { bind(program, PatternPlacement{}, false); }
  // Only the layer array (the stencil path's layer quad).
  void bindLayers(gl::ShaderProgram& program, const PatternPlacement& at) const;
  // What quad.frag's background needs (an image or a colour).
  void bindBackground(gl::ShaderProgram& program, const PatternPlacement& at) const;

 private:
  GpuPalette() = default;
  // Writes the thresholds into the alpha of `chains` (entries' mip chains) where it can.
  void addToneThresholds(const Palette& p, std::vector<std::vector<ImageRGBA8>>& chains);
  gl::Texture layers_;      // GL_TEXTURE_2D_ARRAY, RGBA8, one layer per entry, with mip levels
  gl::Texture layersSrgb_;  // the same texels viewed as sRGB: filtered in linear light
  gl::Texture background_;  // GL_TEXTURE_2D, only for an image background
  std::vector<glm::ivec2> layerSizes_;
  bool sizesDiffer_ = false;
  bool precomposited_ = false;
  bool toneThresholds_ = false;
  std::string toneThresholdNote_;
  bool backgroundImage_ = false;
  glm::vec3 backgroundColour_{1.0f};
  glm::ivec2 backgroundSize_{1, 1};
  std::vector<glm::vec3> averages_;
  PaletteAxis axis_;
  int columns_ = 0;
  glm::vec2 axisMap_{0.0f};

  struct MatcherKey {
    MatchMode mode = MatchMode::Intensity;
    float scale = 0;
    std::vector<float> bands;
    std::optional<glm::vec2> toneTarget;
  };
  struct MatcherSlot {
    std::optional<PaletteMatcher> matcher;
    MatcherKey key;
    unsigned id = 0;
    gl::Texture lutIndex, lutBlend, lut3D;
  };
  std::vector<MatcherSlot> slots_ = std::vector<MatcherSlot>(1);
  mutable int active_ = 0;
  const MatcherSlot& current() const { return slots_[size_t(active_)]; }
  int mipLevels_ = 1;
  std::vector<float> entryAngles_;
  bool anyOriented_ = false;
  // Set when every oriented entry has one stroke angle (sharedStrokeDegrees): that angle in
  // radians, and which entries are turned, one bit each (palette.glsl's uTurnedEntries).
  std::optional<float> sharedAngle_;
  std::vector<int> turnedEntryBits_;
};

}  // namespace npr
