// Palette mip levels: what a palette texture shows when it is drawn smaller than one texel per
// pixel (pattern scale below 1, the anchored pattern's finer octave). A palette's tone must not
// change with scale, or zooming would change the shading: levels are reduced by an
// area-weighted box over the wrapped tile, in linear light with premultiplied alpha, which
// keeps an image's mean light exactly (up to 8-bit rounding) and its tiling seamless.
// Generated palettes bring their own levels (tonal art maps, palettes/generate_palettes.cpp);
// those are used as given.
#pragma once

#include <vector>

#include "renderer/core/image.h"
#include "renderer/palette/palette.h"

namespace npr {

// Levels stop once the smaller side would drop below this: a tile of a few texels holds no
// pattern worth a level of its own.
constexpr int kMinMipSide = 8;

// GL's size of level `level` of a w x h image: each side max(1, side >> level).
inline int mipSide(int side, int level) { return side >> level > 0 ? side >> level : 1; }
// How many levels a w x h texture gets (level 0 included; at least 1).
int mipLevelCount(int width, int height);
// One level down: each side halved (GL's rule), each texel the area-weighted mean of the
// texels it covers, wrapping at the edges.
ImageRGBA8 downsampleHalf(const ImageRGBA8& img);
// An entry's images at levels 0 .. levels-1 as the texture array stores them: composited
// over the background (`background`: the background image's chain, or empty for the solid
// colour) when `precomposited`, straight otherwise. Levels the palette file gave are used as
// given; the others are reduced from the level above.
std::vector<ImageRGBA8> entryMipChain(const PaletteEntry& entry, int levels, bool precomposited, const glm::vec3& bgColour,
                                      const std::vector<ImageRGBA8>& background);
// The background image's chain (reduced only).
std::vector<ImageRGBA8> mipChain(const ImageRGBA8& img, int levels);

// Whether the texture array stores the palette's layers composited over its background: exact
// when the background is a colour, or an image the size of every layer (both tile from the
// same screen corner).
bool layersPrecomposited(const Palette& p);
// The levels a palette's texture array has (its largest layer's).
int paletteMipLevels(const Palette& p);
// Entry i's tone (intensity, 0..3, as the palette analysis measures it) at each mip level the
// renderer will sample.
std::vector<float> entryMipTones(const Palette& p, size_t entry);

}  // namespace npr
