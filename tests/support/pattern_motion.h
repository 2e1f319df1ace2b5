// The slide of a pattern over the surface between two frames (the benchmark's and the tests'
// measure of the shower-door effect): for each covered pixel, where the surface point under it
// goes minus where the pattern texel under it goes, in pixels, averaged. Computed from the
// geometry (eye-space positions read back) and the pattern frames, not from the shader.
#pragma once

#include "renderer/core/camera.h"
#include "renderer/core/image.h"
#include "renderer/patterns/pattern_tracker.h"

namespace npr::test {

// `eyePositions`: this frame's eye-space positions (alpha 0 where nothing was drawn), rows top
// first. `now`/`next`: the frames' pattern frames, or null for the screen (the pattern does not
// move). Every `step`-th pixel in each direction is used.
double patternSlide(const ImageRGBA32F& eyePositions, const CameraMatrices& cameraNow, const CameraMatrices& cameraNext,
                    const PatternFrame* now, const PatternFrame* next, int step = 2);

// The least slide any 2D similarity can have between the two frames: the similarity (rotation,
// uniform scale, translation, from every covered pixel's surface point) whose mean slide over the
// covered pixels is smallest, found by iteratively reweighted least squares (the mean of the
// residuals' lengths is convex in the similarity's four parameters, so it converges to the
// minimum). A floor for the anchored pattern, whatever samples and weights it fits with: what
// is left is parallax, parts of the surface moving unlike any one similarity.
double leastSimilaritySlide(const ImageRGBA32F& eyePositions, const CameraMatrices& cameraNow, const CameraMatrices& cameraNext,
                            int step = 2);

}  // namespace npr::test
