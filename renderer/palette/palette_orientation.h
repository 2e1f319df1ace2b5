// The dominant stroke direction of a palette texture, and how dominant it is: what the
// orientation of hatching (`--orient`) turns each entry by so that its strokes run along the
// surface's direction instead of the texture's own angle.
//
// Measured from a histogram of the image's gradient orientations, weighted by squared
// gradient magnitude (the structure tensor's energy, split by angle). The structure tensor's
// single eigenvector would do for one family of strokes, but crosshatch of two perpendicular
// families has an isotropic tensor: the histogram still finds the stronger family's peak.
// Stipple and blank textures have no peak and are left unrotated.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/image.h"

namespace npr {

struct TextureOrientation {
  // Stroke direction in degrees, counter-clockwise from the screen's x axis (y up, as the
  // texture is shown), in [0, 180).
  float degrees = 0.0f;
  // The share of the gradient energy within 15 degrees of that direction's normal: about
  // 0.17 for no preferred direction, 1 for parallel lines, about 0.5 for even crosshatch.
  float strength = 0.0f;
  static constexpr float kOrientedStrength = 0.35f;
  bool oriented() const { return strength >= kOrientedStrength; }
};

// `img` as shown over a background of colour `background` (encoded): alpha composited,
// luminance, tiled (gradients wrap around the edges, as the texture repeats on screen).
TextureOrientation textureOrientation(const ImageRGBA8& img, const glm::vec3& background);

// The one stroke direction (degrees, [0, 180)) a palette's oriented entries share, each within
// kSharedStrokeTolerance degrees of it (the analysis' own accuracy on line textures): their
// mean, taken on doubled angles so that 179 and 1 agree. Nullopt when they differ or none is
// oriented. Turning every oriented entry by one angle lets the shader compute the turn once
// per pixel, before it knows the entry (palette.glsl).
constexpr float kSharedStrokeTolerance = 2.0f;
std::optional<float> sharedStrokeDegrees(const std::vector<TextureOrientation>& entries);

}  // namespace npr
