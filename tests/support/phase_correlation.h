// How far one image's content moved to make another, to a fraction of a pixel: phase
// correlation (the normalised cross-power spectrum's inverse peaks at the whole-pixel shift),
// refined by the slope of the spectrum's phase. What the tests use to tell that a pattern
// moved with a panned object, and by how much.
#pragma once

#include <glm/glm.hpp>

#include "renderer/core/image.h"

namespace npr::test {

// The shift d, in pixels (x right, y down the rows), with b(p) = a(p - d) around the window
// [x0, x0 + n) x [y0, y0 + n) (luminance, a Hann window against the edges). Shifts up to n/2
// in either direction are told apart; b is read again at the window moved by the whole-pixel
// shift, so give it that much margin (the window is clamped to the image).
glm::vec2 phaseCorrelationShift(const ImageRGBA8& a, const ImageRGBA8& b, int x0, int y0, int n);

}  // namespace npr::test
