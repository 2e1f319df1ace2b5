// Anchored screen-space patterns (after Breslav et al. 2007, "Dynamic 2D Patterns for Shading
// 3D Scenes"): the palette stays flat to the camera but follows the object as it moves. A
// fixed set of sample points on the surface is projected each frame; the 2D similarity
// (translation, rotation, uniform scale) that best carries the visible samples' previous
// screen positions to their current ones (weighted least squares) is accumulated into the
// pattern's frame, which the shaders apply to each pixel before the palette lookup
// (palette.glsl, quad.frag). CPU cost: a few hundred points per frame, whatever the mesh.
// A close-up leaves few of those points in view (a square zoomed into had none at 34x), so
// then points are drawn afresh from what the view shows and tracked instead, until the fixed
// ones suffice again; drawing them scans at most kScanFaces faces (0.2 ms on the bunny,
// 1.3-1.7 ms on the 871K torus, on the frames that draw them).
#pragma once

#include <cstddef>
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
  bool reset = false;    // the frame was restarted (first frame, jump)
  bool resampled = false;  // close-up: points were drawn afresh from the view this frame
};

class PatternTracker {
 public:
  static constexpr int kSamples = 384;
  // Fewer fixed samples than this in view, in both frames: track points drawn from the view.
  static constexpr int kCloseUpBelow = 48;
  static constexpr std::size_t kScanFaces = 65536;

  // Picks the sample points (area-weighted, deterministic) and restarts the frame.
  void setMesh(const Mesh* mesh);
  // Starts again from the identity at the next update (view jumps: frame, reset, new model).
  void reset() {
    havePrevious_ = false;
    frame_ = {};
    closeUp_.clear();
  }
  // Fits this frame's motion and accumulates it. `followRotation` false keeps the pattern
  // upright (translation and scale only).
  const PatternFit& update(const CameraMatrices& camera, const glm::ivec4& viewport, bool followRotation);

  const PatternFrame& frame() const { return frame_; }
  const PatternFit& lastFit() const { return fit_; }

 private:
  struct Sample {
    glm::vec3 position, normal;
    float area;  // what it stands for: object-space area (fixed) or its equivalent (close-up)
  };
  // One frame's camera: where a point lands on screen and whether it counts as seen there.
  struct View {
    glm::mat4 mvp{1.0f};
    glm::vec3 eye{0.0f};
    glm::ivec4 viewport{0};
    static View of(const CameraMatrices& camera, const glm::ivec4& viewport);
    bool project(const glm::vec3& position, const glm::vec3& normal, glm::vec2& screen) const;
  };
  // Samples seen in both frames: their screen positions then and now, and their weights.
  struct Pairs {
    std::vector<glm::vec2> from, to;
    std::vector<float> weights;
  };
  static void gather(const std::vector<Sample>& samples, const View& before, const View& now, Pairs& out);
  // Draws kSamples points uniformly over the mesh's front faces' pixels in `now` (closeUp_).
  void sampleCloseUp(const View& now);

  const Mesh* mesh_ = nullptr;
  std::vector<Sample> samples_;  // fixed, area-weighted over the whole surface
  std::vector<Sample> closeUp_;  // drawn from a close-up view; empty when the fixed ones do
  Pairs pairs_, closeUpPairs_;
  View previous_;
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
