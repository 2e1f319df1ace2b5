// Crisp tone between two nested levels (after Webb, Praun, Finkelstein and Hoppe 2002, "Fine
// tone control in hardware hatching"). Blending two levels of a tonal art map greys their
// strokes; instead each texel gets the fraction of the way from one level to the next at which
// it turns to the darker one, and a pixel shows whole texels of one level or the other
// (`--tone-blend threshold`: one comparison, the same two fetches as the blend). The fractions
// come from the levels themselves: the texels each level adds are grouped into connected marks
// (strokes, dots), the marks are taken in a fixed random order, and a mark's fraction is the
// share of the added darkness that comes before it, so the darkness shown grows evenly with
// the fraction. Marks larger than a sixteenth of what a level adds (crossing strokes merge)
// are cut into pieces along their own flood fill, so no mark makes the tone jump.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/core/image.h"
#include "renderer/core/result.h"

namespace npr {

// `lightToDark`: one mip level of every entry, lightest first, the same size, as the texture
// stores them (composited over the paper). Per texel, the fraction in [0, 1] as a byte; an
// error naming the first pair of levels that is not nested (more than 2% of the texels get
// lighter by more than 0.1 of the paper's light) or the sizes that differ.
// `requireMarks`: refuse a ramp (see kMarkCover); a palette's coarse mip levels, blurred
// into ramps, are taken as they come once level 0 has passed.
[[nodiscard]] Result<std::vector<std::uint8_t>> toneThresholds(const std::vector<const ImageRGBA8*>& lightToDark, bool requireMarks = true);

struct Palette;
// The thresholds of a palette's stored layers at mip level `level`: `chains` holds every
// entry's mip chain as the texture stores it (palette_mipmaps.h's entryMipChain), the levels
// are taken lightest first. An error saying why a palette has none: its layers are not stored
// composited over the background (then alpha is theirs), differ in size, do not nest or (at
// level 0) are a ramp.
// `row`: a palette with rows (palette.h) is thresholded along each row's tone ladder.
[[nodiscard]] Result<std::vector<std::uint8_t>> paletteToneThresholds(const Palette& p, const std::vector<std::vector<ImageRGBA8>>& chains,
                                                                    std::size_t level, int row = 0);
// The same at level 0, the chains made here, every row checked (the last row's returned):
// what --palette-info reports.
[[nodiscard]] Result<std::vector<std::uint8_t>> paletteToneThresholds(const Palette& p);

// What a pixel shows between levels `pair` and `pair + 1` at weight `w` (0: the lighter
// level, 1: the darker), measured over the tile in linear light: the tone as a position in
// levels (pair + the share of the way between the two levels' mean light) and the standard
// deviation of the light, for the threshold (whole texels of one level or the other) and for
// the mix (today's blend). `single`: a single level's standard deviation at that tone, the two
// levels' interpolated (a level drawn for the tone in between would have about that).
struct ToneBlendMeasure {
  double thresholdTone = 0, mixTone = 0;
  double thresholdSpread = 0, mixSpread = 0, single = 0;
  // Crispness: the share of texels at a mid grey (between a quarter and three quarters of the
  // way from ink to paper), for each and for a single level (interpolated, as `single`).
  double thresholdGrey = 0, mixGrey = 0, singleGrey = 0;
};
ToneBlendMeasure measureToneBlend(const std::vector<const ImageRGBA8*>& lightToDark, const std::vector<std::uint8_t>& thresholds,
                                  std::size_t pair, double w);

}  // namespace npr
