// Palette upload, lookup tables and binding (see gpu_palette.h).
#include "renderer/palette/gpu_palette.h"

#include <cmath>

#include <algorithm>
#include <cstring>
#include <string>

#include "renderer/gl/texture.h"
#include "renderer/gl/texture_units.h"
#include "renderer/palette/palette_analysis.h"
#include "renderer/palette/palette_mipmaps.h"
#include "renderer/palette/palette_orientation.h"
#include "renderer/palette/tone_thresholds.h"

namespace npr {
namespace {
// This file's samplers' texture units (gl/texture_units.h).
const gl::TextureUnit kBackgroundUnit = gl::claimTextureUnit();  // the palette's background image
const gl::TextureUnit kLut3DUnit = gl::claimTextureUnit();  // matcher: colours mode grid
const gl::TextureUnit kLutBlendUnit = gl::claimTextureUnit();  // matcher: bracketing entries and weight per tone bin
const gl::TextureUnit kLutIndexUnit = gl::claimTextureUnit();  // matcher: nearest entry per tone bin
const gl::TextureUnit kPaletteUnit = gl::claimTextureUnit();  // palette layers (GL_TEXTURE_2D_ARRAY)
}  // namespace
namespace {

using gl::TextureUnit;

// Images are stored top row first; GL's rows start at the bottom of the screen.
const std::uint8_t* flipRows(const ImageRGBA8& img, std::vector<std::uint8_t>& out) {
  const size_t row = static_cast<size_t>(img.width) * 4;
  out.resize(img.pixels.size());
  for (int y = 0; y < img.height; ++y)
    std::memcpy(&out[static_cast<size_t>(img.height - 1 - y) * row], &img.pixels[static_cast<size_t>(y) * row], row);
  return out.data();
}

unsigned nextMatcherId() {
  static unsigned id = 0;
  return ++id;
}

}  // namespace

Result<std::unique_ptr<GpuPalette>> GpuPalette::upload(const Palette& p) {
  const int n = static_cast<int>(p.entries.size());
  if (n < 1 || n > kMaxPaletteEntries) return Error{"palette must have 1.." + std::to_string(kMaxPaletteEntries) + " entries"};
  GLint maxLayers = 0, maxSize = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (n > maxLayers) return Error{"palette has " + std::to_string(n) + " entries; this GPU holds " + std::to_string(maxLayers) + " layers"};
  std::unique_ptr<GpuPalette> gp(new GpuPalette());
  int w = 1, h = 1;
  std::vector<TextureOrientation> orientations;
  for (const auto& e : p.entries) {
    orientations.push_back(e.orientation);
    w = std::max(w, e.image.width);
    h = std::max(h, e.image.height);
    gp->layerSizes_.push_back({e.image.width, e.image.height});
    gp->entryAngles_.push_back(e.orientation.oriented() ? float(e.orientation.degrees * M_PI / 180.0) : -100.0f);
    gp->anyOriented_ |= e.orientation.oriented();
    gp->sizesDiffer_ |= gp->layerSizes_.back() != gp->layerSizes_.front();
  }
  if (const std::optional<float> shared = sharedStrokeDegrees(orientations)) {
    gp->sharedAngle_ = float(*shared * M_PI / 180.0);
    // Every path turns by the same angle, the stencil path's per-layer quads included.
    for (float& a : gp->entryAngles_)
      if (a > -10.0f) a = *gp->sharedAngle_;
    gp->turnedEntryBits_.assign(size_t(n + 31) / 32, 0);
    for (int k = 0; k < n; ++k)
      if (orientations[size_t(k)].oriented()) gp->turnedEntryBits_[size_t(k) / 32] |= int(1u << (k % 32));
  }
  if (w > maxSize || h > maxSize)
    return Error{"palette texture " + std::to_string(w) + "x" + std::to_string(h) + " exceeds this GPU's limit " + std::to_string(maxSize)};
  const ImageRGBA8* bg = p.backgroundImage ? &*p.backgroundImage : nullptr;
  // Precompositing each layer over the background is exact when the background is a solid
  // colour or an image the size of every layer (both tile from the same screen corner).
  gp->precomposited_ = layersPrecomposited(p);
  gp->backgroundColour_ = p.backgroundColour;
  gp->averages_ = p.averages();
  gp->axis_ = p.axis;
  gp->columns_ = p.columns();
  std::vector<std::uint8_t> flipped;
  gp->mipLevels_ = mipLevelCount(w, h);
  const int levels = gp->mipLevels_;
  const std::vector<ImageRGBA8> bgChain = gp->precomposited_ && bg ? mipChain(*bg, levels) : std::vector<ImageRGBA8>{};
  gp->layers_ = gl::createTexture();
  glActiveTexture(GL_TEXTURE0 + gl::unitIndex(kPaletteUnit));
  glBindTexture(GL_TEXTURE_2D_ARRAY, gp->layers_.id());
  // Immutable storage, so a second view can read the same texels as sRGB (below).
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, levels, GL_RGBA8, w, h, n);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  std::vector<std::vector<ImageRGBA8>> chains;
  for (int i = 0; i < n; ++i)
    chains.push_back(entryMipChain(p.entries[static_cast<size_t>(i)], levels, gp->precomposited_, p.backgroundColour, bgChain));
  gp->addToneThresholds(p, chains);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < levels; ++k) {
      const ImageRGBA8& img = chains[size_t(i)][size_t(k)];
      glTexSubImage3D(GL_TEXTURE_2D_ARRAY, k, 0, 0, i, img.width, img.height, 1, GL_RGBA, GL_UNSIGNED_BYTE, flipRows(img, flipped));
    }
  // Read with texelFetch (encoded values, no filtering) at one texel per pixel, and where
  // layers differ in size.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  // Filtering must average light, not encoded values: between paper and ink an encoded average
  // is darker than the light it stands for (a bilinear crosshatch at 2 pixels a texel lost
  // half a palette step of tone). Filtered patterns therefore read an sRGB view of the same
  // texels and encode the result again (pattern.glsl).
  gp->layersSrgb_ = gl::createTexture();
  glTextureView(gp->layersSrgb_.id(), GL_TEXTURE_2D_ARRAY, gp->layers_.id(), GL_SRGB8_ALPHA8, 0, GLuint(levels), 0, GLuint(n));
  glBindTexture(GL_TEXTURE_2D_ARRAY, gp->layersSrgb_.id());
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
  if (bg) {
    gp->backgroundImage_ = true;
    gp->backgroundSize_ = {bg->width, bg->height};
    gp->background_ = gl::createTexture();
    glActiveTexture(GL_TEXTURE0 + gl::unitIndex(kBackgroundUnit));
    glBindTexture(GL_TEXTURE_2D, gp->background_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, bg->width, bg->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, flipRows(*bg, flipped));
    gl::setNearestSingleLevel(GL_TEXTURE_2D);
  }
  glActiveTexture(GL_TEXTURE0);
  if (glGetError() == GL_OUT_OF_MEMORY) return Error{"palette upload failed: out of GPU memory"};
  return gp;
}

void GpuPalette::addToneThresholds(const Palette& p, std::vector<std::vector<ImageRGBA8>>& chains) {
  toneThresholds_ = false;
  // Row by row (a palette with rows nests along each row's tone ladder); all or nothing.
  const int rows = std::max(p.axis.rows, 1);
  const std::size_t columns = std::size_t(p.columns());
  std::vector<std::vector<std::vector<std::uint8_t>>> rowLevels;
  for (int r = 0; r < rows; ++r) {
    std::vector<std::vector<std::uint8_t>> levels;
    for (std::size_t k = 0; k < chains.front().size(); ++k) {
      Result<std::vector<std::uint8_t>> t = paletteToneThresholds(p, chains, k, r);
      if (!t && k == 0) {
        toneThresholdNote_ = rows > 1 ? "row " + std::to_string(r + 1) + ": " + t.error() : t.error();  // alpha left as it was
        return;
      }
      if (!t) {
        // A coarse level whose reduced strokes no longer nest: every other texel of the finer
        // level's thresholds, the marks kept in the same order.
        const ImageRGBA8& fine = chains.front()[k - 1];
        const ImageRGBA8& coarse = chains.front()[k];
        std::vector<std::uint8_t> sub(std::size_t(coarse.width) * std::size_t(coarse.height));
        for (int y = 0; y < coarse.height; ++y)
          for (int x = 0; x < coarse.width; ++x)
            sub[std::size_t(y) * std::size_t(coarse.width) + std::size_t(x)] =
                levels.back()[std::size_t(std::min(2 * y, fine.height - 1)) * std::size_t(fine.width) + std::size_t(std::min(2 * x, fine.width - 1))];
        t = std::move(sub);
      }
      levels.push_back(std::move(*t));
    }
    rowLevels.push_back(std::move(levels));
  }
  for (std::size_t e = 0; e < chains.size(); ++e) {
    const auto& levels = rowLevels[std::min(e / std::max<std::size_t>(columns, 1), rowLevels.size() - 1)];
    for (std::size_t k = 0; k < levels.size(); ++k)
      for (std::size_t j = 0; j < levels[k].size(); ++j) chains[e][k].pixels[4 * j + 3] = levels[k][j];
  }
  toneThresholds_ = true;
  toneThresholdNote_.clear();
}

Status GpuPalette::updateMatcher(MatchMode mode, float scale, const std::vector<float>& bands, FrameStats& stats,
                                 std::optional<glm::vec2> toneTarget, int slot) {
  if (slot < 0 || slot > 4096) return Error{"matcher slot " + std::to_string(slot) + " out of range"};
  if (size_t(slot) >= slots_.size()) slots_.resize(size_t(slot) + 1);
  MatcherSlot& m = slots_[size_t(slot)];
  if (m.matcher && m.key.mode == mode && m.key.scale == scale && m.key.bands == bands && m.key.toneTarget == toneTarget) return okStatus();
  // A palette with rows matches against its first row: the tone picks the column (palette.h).
  const std::vector<glm::vec3> columnAverages(averages_.begin(), averages_.begin() + columns_);
  Result<PaletteMatcher> made = PaletteMatcher::create(columnAverages, mode, scale, bands, toneTarget);
  if (!made) return Error{made.error()};
  m.matcher = std::move(*made);
  m.key = {mode, scale, bands, toneTarget};
  m.id = nextMatcherId();
  ++stats.lutBuilds;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (mode == MatchMode::Colors) {
    const int G = PaletteMatcher::kLut3DSize;
    const std::vector<std::uint8_t> lut = m.matcher->buildLut3D();
    m.lut3D = gl::createTexture();
    glActiveTexture(GL_TEXTURE0 + gl::unitIndex(kLut3DUnit));
    glBindTexture(GL_TEXTURE_3D, m.lut3D.id());
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RG8UI, G, G, G, 0, GL_RG_INTEGER, GL_UNSIGNED_BYTE, lut.data());
    gl::setNearestSingleLevel(GL_TEXTURE_3D);
  } else {
    const int L = PaletteMatcher::kLut1DSize;
    const std::vector<std::uint8_t> index = m.matcher->buildLutIndex1D();
    const std::vector<float> blend = m.matcher->buildLutBlend1D();
    m.lutIndex = gl::createTexture();
    glActiveTexture(GL_TEXTURE0 + gl::unitIndex(kLutIndexUnit));
    glBindTexture(GL_TEXTURE_2D, m.lutIndex.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, L, 1, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, index.data());
    gl::setNearestSingleLevel(GL_TEXTURE_2D);
    m.lutBlend = gl::createTexture();
    glActiveTexture(GL_TEXTURE0 + gl::unitIndex(kLutBlendUnit));
    glBindTexture(GL_TEXTURE_2D, m.lutBlend.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, L, 1, 0, GL_RGBA, GL_FLOAT, blend.data());
    gl::setNearestSingleLevel(GL_TEXTURE_2D);
  }
  glActiveTexture(GL_TEXTURE0);
  ++stats.bufferUploads;
  return okStatus();
}

void GpuPalette::setAxisScale(float sceneRadius) {
  // The axis value in the shader's units: depth is an eye-space distance, scene radii times the radius.
  axisMap_ = axis_.map(axis_.kind == PaletteAxisKind::Depth ? std::max(sceneRadius, 1e-6f) : 1.0f);
}

float GpuPalette::rowPosition(const glm::vec3& eyePosition, const glm::vec3& eyeNormal, float detail) const {
  if (axis_.rows < 2) return 0.0f;
  return paletteRowAt(paletteAxisValue(axis_.kind, eyePosition, eyeNormal, detail), axisMap_, axis_.rows);
}

gl::PaletteVariant GpuPalette::variant(MatchMode mode, const PatternPlacement& at) const {
  gl::PaletteVariant v;
  v.size = size();
  v.layerSizesDiffer = sizesDiffer_;
  v.precomposited = precomposited_;
  v.backgroundImage = backgroundImage_;
  v.match = mode;
  v.pattern = at.mapping();
  v.filtered = filtered(at);
  v.orientBins = orientBins(at);
  v.entryAngleShared = v.orientBins > 0 && sharedAngle_.has_value();
  v.patternPerVertex = at.perVertex && gl::mapsScreenPosition(v.pattern);
  if (axis_.rows > 1) {
    v.rows = axis_.rows;
    v.columns = columns_;
    v.axis = axis_.kind;
  }
  return v;
}

gl::StrokeSource GpuPalette::strokeSource(const PatternPlacement& at) const {
  if (!oriented(at)) return gl::StrokeSource::None;
  switch (at.orient.source) {
    case OrientSource::Curvature: return gl::StrokeSource::Field;
    case OrientSource::Light: return gl::StrokeSource::Light;
    case OrientSource::Fixed: return gl::StrokeSource::Fixed;
    case OrientSource::None: break;
  }
  return gl::StrokeSource::None;
}

void GpuPalette::bindStrokeSource(gl::ShaderProgram& prog, const PatternPlacement& at) const {
  switch (strokeSource(at)) {
    case gl::StrokeSource::Fixed: prog.set("uOrientFixed", float(at.orient.degrees * M_PI / 180.0)); break;
    case gl::StrokeSource::Light:
      prog.set("uOrientLight", at.light);
      prog.set("uViewportSize", glm::vec2(at.viewport.z, at.viewport.w));
      break;
    case gl::StrokeSource::Field: prog.set("uViewportSize", glm::vec2(at.viewport.z, at.viewport.w)); break;
    case gl::StrokeSource::None: break;
  }
}

void GpuPalette::bindOrientation(gl::ShaderProgram& prog, const PatternPlacement& at) const {
  if (!oriented(at)) return;
  const int bins = at.orient.bins;
  std::vector<glm::vec2> steps(static_cast<size_t>(bins));
  for (int b = 0; b < bins; ++b) {
    const double a = M_PI * b / bins;
    steps[static_cast<size_t>(b)] = glm::vec2(float(std::cos(a)), float(std::sin(a)));
  }
  prog.setArray("uBinRotation", steps.data(), bins);
  prog.set("uFrameTurn", at.frame ? at.frame->rotation : 0.0f);
}

namespace {
// Nearest lookups of mapped patterns are shifted by a fixed fraction of a texel: at a rational
// scale pixel centres otherwise land exactly on texel edges (at 1.5 every third column), where
// any rounding picks either texel and a poster's tiles, whose pixels are mapped from other
// offsets, could differ from one frame. 0.0371 lies off the multiples of 1 / 2a that scales a / b
// put centres at, for a < 27. Filtered lookups change continuously there: unshifted, texel
// centres stay exact.
constexpr float kTexelShift = 0.0371f;

}  // namespace

int GpuPalette::lodFor(float texelsPerPixel) const {
  if (!(texelsPerPixel > std::sqrt(2.0f))) return 0;
  return std::min(mipLevels_ - 1, int(std::lround(std::log2(texelsPerPixel))));
}

void GpuPalette::bindPattern(gl::ShaderProgram& prog, const PatternPlacement& at) const {
  if (at.mapping() == gl::PatternMapping::Screen) return;
  // A fixed scale is the identity frame; the anchored frame's scale is split into octaves (the
  // coarse layer's marks are S 2^octave pixels wide; only PATTERN_ANCHORED reads the fine one,
  // and where the dissolve is complete the fine octave is drawn alone, as the coarse one).
  const PatternFrame frame = at.frame.value_or(PatternFrame{});
  const OctaveSplit split = at.octaves();
  const float markSize = at.scale * std::exp2(split.fade >= 1.0f ? split.octave - 1.0f : split.octave);
  const float c = std::cos(frame.rotation), s = std::sin(frame.rotation);
  // u = R(-rotation) (x + frameOffset - origin) / markSize, column-major.
  const glm::mat2 m = glm::mat2(c, -s, s, c) / markSize;
  const glm::vec2 offset = m * (at.frameOffset - frame.translation) + glm::vec2(filtered(at) ? 0.0f : kTexelShift);
  prog.set("uPatternMatrix", glm::vec4(m[0], m[1]));
  prog.set("uPatternOffset", offset);
  // The same from clip positions (pattern_vertex.glsl): a pixel is S/2 (clip / w + 1) + O for
  // the viewport's size S and corner O, so u w = M S/2 clip.xy + (M (S/2 + O) + offset) w.
  const glm::vec2 half = glm::vec2(at.viewport.z, at.viewport.w) * 0.5f;
  const glm::mat2 clip = m * glm::mat2(half.x, 0.0f, 0.0f, half.y);
  prog.set("uPatternClipMatrix", glm::vec4(clip[0], clip[1]));
  prog.set("uPatternClipOffset", m * (half + glm::vec2(at.viewport.x, at.viewport.y)) + offset);
  prog.set("uPatternFade", split.fade);
  prog.set("uPatternLod", glm::vec2(float(lodFor(1.0f / markSize)), float(lodFor(2.0f / markSize))));
  if (at.object) {
    // Octaves are chosen per pixel from its depth (pattern.glsl); the coarse one's texels are
    // 1 to 2 pattern-scale pixels wide, the fine one's read one level down: the levels above,
    // whose frame is the identity here (octave 0, marks of the pattern scale).
    prog.set("uPixelSize", at.pixelSize);
    prog.set("uEyeToObject", at.eyeToObject);
    prog.set("uPatternScale", at.scale);
  }
}

void GpuPalette::bindLayers(gl::ShaderProgram& prog, const PatternPlacement& at) const {
  prog.set("uFrameOffset", at.frameOffset);
  // Filtered lookups (pattern.glsl's mappedTexel) read the sRGB view.
  gl::bindTexture(kPaletteUnit, GL_TEXTURE_2D_ARRAY, filtered(at) ? layersSrgb_.id() : layers_.id());
  prog.set("uPalette", gl::unitIndex(kPaletteUnit));
}

void GpuPalette::bindBackground(gl::ShaderProgram& prog, const PatternPlacement& at) const {
  prog.set("uFrameOffset", at.frameOffset);
  if (backgroundImage_) {
    gl::bindTexture(kBackgroundUnit, GL_TEXTURE_2D, background_.id());
    prog.set("uBackground", gl::unitIndex(kBackgroundUnit));
    prog.set("uBackgroundSize", backgroundSize_);
    prog.set("uBackgroundScale", 1.0f / at.scale);
  } else {
    prog.set("uBackgroundColour", backgroundColour_);
  }
}

void GpuPalette::bind(gl::ShaderProgram& prog, const PatternPlacement& at, bool turned) const {
  bindLayers(prog, at);
  if (sizesDiffer_) prog.setArray("uLayerSize", layerSizes_.data(), size());
  else prog.set("uLayerSize0", layerSizes_[0]);
  bindBackground(prog, at);
  bindPattern(prog, at);
  if (axis_.rows > 1) prog.set("uAxisMap", axisMap_);
  if (turned && oriented(at)) {
    if (sharedAngle_) {
      prog.set("uSharedEntryAngle", *sharedAngle_);
      prog.setArray("uTurnedEntries", turnedEntryBits_.data(), int(turnedEntryBits_.size()));
    } else {
      prog.setArray("uEntryAngle", entryAngles_.data(), size());
    }
    bindOrientation(prog, at);
    bindStrokeSource(prog, at);
  }
  const MatcherSlot& m = current();
  if (m.matcher && m.matcher->mode() == MatchMode::Colors) {
    gl::bindTexture(kLut3DUnit, GL_TEXTURE_3D, m.lut3D.id());
    prog.set("uLut3D", gl::unitIndex(kLut3DUnit));
    prog.setArray("uAverages", m.matcher->scaledAverages().data(), m.matcher->size());
  } else {
    gl::bindTexture(kLutIndexUnit, GL_TEXTURE_2D, m.lutIndex.id());
    prog.set("uLutIndex", gl::unitIndex(kLutIndexUnit));
    gl::bindTexture(kLutBlendUnit, GL_TEXTURE_2D, m.lutBlend.id());
    prog.set("uLutBlend", gl::unitIndex(kLutBlendUnit));
  }
}

}  // namespace npr
