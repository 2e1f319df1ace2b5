// An OBJ material's opacity map (map_d) folded into its diffuse map's alpha, which is what the
// renderer's coverage reads (shaders/coverage.glsl): MTL keeps the two apart, glTF and the GPU
// material table have one map whose alpha is the surface's.
#pragma once

#include "renderer/core/image.h"

namespace npr {

// `colour` (null: white) with its alpha multiplied by `opacity` sampled at the same texture
// coordinate (nearest texel; the maps may differ in size). The opacity is the map's alpha where
// it has any below 255, else its luminance (a grey map, as most exporters write). The result is
// `colour`'s size, or `opacity`'s without a colour map.
ImageRGBA8 withOpacityMap(const ImageRGBA8* colour, const ImageRGBA8& opacity);

}  // namespace npr
