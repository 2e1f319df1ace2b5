// Anchored screen-space patterns (after Breslav et al. 2007, "Dynamic 2D Patterns for Shading
// 3D Scenes"): the palette stays flat to the camera but follows the object as it moves. A
// fixed set of sample points on the surface is projected each frame; the 2D similarity
// (translation, rotation, uniform scale) that best carries the visible samples' previous
// screen positions to their current ones (weighted least squares) is accumulated into the
// pattern's frame, which the shaders apply to each pixel before the palette lookup
// (palette.glsl, quad.frag). CPU cost: a few hundred points per frame, whatever the mesh.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/mesh/mesh.h"

namespace npr {

// Pattern coordinates to window pixels: x = scale R(rotation) u + translation.
struct PatternFrame {
  glm::vec2 translation{0.0f};
  float rotation = 0.0f;  // radians
  float scale = 1.0f;
};

// What one frame's fit found (for the overlay and the benchmark).
struct PatternFit {
  int samplesUsed = 0;   // visible in both frames
  float residualPx = 0;  // weighted RMS distance left after the fit, in pixels
  double ms = 0;         // CPU time of the update
  bool reset = false;    // the frame was restarted (first frame, jump, too few samples)
};

class PatternTracker {
 public:
  static constexpr int kSamples = 384;

  // Picks the sample points (area-weighted, deterministic) and restarts the frame.
  void setMesh(const Mesh* mesh);
  // Starts again from the identity at the next update (view jumps: frame, reset, new model).
  void reset() { havePrevious_ = false; frame_ = {}; }
  // Fits this frame's motion and accumulates it. `followRotation` false keeps the pattern
  // upright (translation and scale only).
  const PatternFit& update(const CameraMatrices& camera, const glm::ivec4& viewport, bool followRotation);

  const PatternFrame& frame() const { return frame_; }
  const PatternFit& lastFit() const { return fit_; }

 private:
  struct Sample {
    glm::vec3 position, normal;
    float area;
  };
  std::vector<Sample> samples_;
  std::vector<glm::vec2> previous_;
  std::vector<char> previousVisible_;
  bool havePrevious_ = false;
  PatternFrame frame_;
  PatternFit fit_;
};

// The similarity taking `from` to `to` (weighted least squares; the scale is the ratio of the
// two point sets' weighted spreads, so fitting back and forth gives reciprocal scales and the
// pattern does not drift in size). Exposed for tests.
PatternFrame fitSimilarity(const std::vector<glm::vec2>& from, const std::vector<glm::vec2>& to, const std::vector<float>& weights,
                           bool followRotation);

}  // namespace npr
