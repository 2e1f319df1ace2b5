// The regions of a label image (each pixel's palette entry, from the selection output) traced
// into polygons for the SVG's fills (`--svg-fill`): every region's boundary follows the pixel
// edges, outer boundaries clockwise on screen and holes counter-clockwise, corners only. Filled
// with SVG's nonzero rule, a label's polygons cover exactly its pixels, so the vector picture
// matches the raster one pixel for pixel away from antialiased edges. No GL here.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace npr {

using RegionLoop = std::vector<glm::ivec2>;  // corners in pixel coordinates, y down, closed

// Per label 0..labelCount-1, its loops; pixels with a label outside that range (no surface) are
// left out. `labels` holds width x height labels, rows top first.
std::vector<std::vector<RegionLoop>> traceRegions(const std::vector<int>& labels, int width, int height, int labelCount);

}  // namespace npr
