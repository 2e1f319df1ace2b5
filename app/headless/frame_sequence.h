// Which frames a headless run renders and where each one's scene and camera stand, so that a
// frame comes out the same whether the whole sequence is rendered or only a range holding it
// (--frame-range: a render farm splits a sequence over machines).
//   - The scene clock is derived from the frame number: --time + f / --fps, looped over the
//     animations' length (not summed frame by frame, which would drift apart from a range).
//   - The camera is the start camera moved f steps of the scripted motion (--animate,
//     --turntable): the steps are a few multiplications, taken for the frames before a range too.
//   - The anchored pattern follows the model from frame to frame: a range warms it up by
//     following the frames before it without drawing them (Renderer::follow: a few hundred
//     points projected per object and frame).
//   - A turntable turns the model under the light: the light turns with the camera's orbit
//     (turntableLight), so the far side is lit as the near side was, as on a real turntable.
// Everything else a frame shows (the tone fit, brush strokes, the occlusion bake) is a function
// of the frame alone.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "renderer/core/result.h"

namespace npr {

// Frames FIRST to LAST of the sequence, both included, numbered from 0 as --save-frames names
// them (frame-0003.png).
struct FrameRange {
  int first = 0, last = 0;
  int count() const { return last - first + 1; }
};

// "FIRST-LAST" or "N" (one frame), for a sequence of `frames` frames: a range outside it, or
// backwards, is an error naming what is allowed.
[[nodiscard]] Result<FrameRange> parseFrameRange(const std::string& spec, int frames);

// The scene clock at frame `f` of a sequence starting at `start` seconds, stepping 1 / `fps`
// of scene time per frame at `speed`, looped over `length` seconds (0: a still scene).
double sequenceTime(double start, int f, double fps, double speed, double length);

// Where a turntable's light stands when the camera has orbited `degrees` about the vertical
// axis through `centre`: `light` turned with it.
glm::vec3 turntableLight(const glm::vec3& light, const glm::vec3& centre, float degrees);

}  // namespace npr
