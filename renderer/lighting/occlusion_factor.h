// How much of the ambient and diffuse light an ambient-occlusion value (1: open, 0: enclosed)
// leaves at a strength (--occlusion-strength; 0: none of it, 1: all): the one formula the CPU's
// per-triangle lighting and the benchmark's ray-traced reference use. shaders/
// occlusion_factor.glsl is the same on the GPU; the uniform takes occlusionStrength()'s value.
#pragma once

#include <algorithm>
#include <cmath>

namespace npr {

// The strength in [0, 1] (not a number: 0).
template <class T>
T occlusionStrength(T strength) {
  return std::isnan(strength) ? T(0) : std::clamp(strength, T(0), T(1));
}

template <class T>
T occlusionFactor(T occlusion, T strength) {
  return T(1) + (std::clamp(occlusion, T(0), T(1)) - T(1)) * occlusionStrength(strength);
}

}  // namespace npr
