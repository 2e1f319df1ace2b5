// How well rendered hatching follows the wanted directions (the orientation tests' and the
// benchmark's measures), from images read back, not from the shader:
//  - the local stroke orientation of a rendered frame, from the structure tensor of its
//    luminance over a Gaussian window;
//  - its median angle to the stroke angles the renderer wanted (Renderer::renderStrokeAngles);
//  - how often a surface point's orientation step jumps by more than one between two frames,
//    following each point into the next frame through the eye-space positions.
#pragma once

#include <cstddef>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/core/image.h"

namespace npr::test {

struct StrokeOrientation {
  int width = 0, height = 0;
  std::vector<float> angle;      // radians in [0, pi), counter-clockwise from x, y up (rows top first)
  std::vector<float> coherence;  // in [0, 1]: 0 no direction (blank, solid, dots), 1 parallel strokes
};
StrokeOrientation strokeOrientation(const ImageRGBA8& img, float sigma = 3.0f);

struct Alignment {
  double medianDegrees = 90.0;  // median angle between the strokes seen and the strokes wanted
  std::size_t pixels = 0;       // pixels compared: wanted angle valid, strokes coherent
};
// `wanted`: renderStrokeAngles' output (angle, valid) at the same size; `offset` is added to
// every wanted angle (compare with 0 and pi/2 to show strokes are not at the texture's angle).
Alignment strokeAlignment(const ImageRGBA8& img, const ImageRGBA32F& wanted, double offset = 0.0, double minCoherence = 0.5);

// Fraction of surface pixels of frame `now` whose orientation step (K steps over pi, of the
// wanted angle minus `entryAngle`) differs by more than one step from the step of the same
// surface point in frame `next`. Points hidden or off screen in `next` are skipped.
double stepJumpFraction(const ImageRGBA32F& anglesNow, const ImageRGBA32F& eyeNow, const CameraMatrices& cameraNow,
                        const ImageRGBA32F& anglesNext, const ImageRGBA32F& eyeNext, const CameraMatrices& cameraNext, int bins,
                        float entryAngle = 0.0f, std::size_t* compared = nullptr);

}  // namespace npr::test
