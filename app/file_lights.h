// The scene files' lights (KHR_lights_punctual) as OpenGL lights. GL's lights have no units
// and a palette renders tone, not exposure, so each light keeps its colour and its strength
// relative to the others:
//   E = intensity (lux) for a directional light, intensity / d^2 (candela over the squared
//       distance in the file's units from the light to the scene's centre) for point and spot
//       lights; diffuse = specular = colour * E / max E (the brightest light is GL's full one);
//   no falloff across the scene (constant attenuation): a tone would swing over one object;
//   spot cutoff = the outer cone angle, exponent e with cos(mid)^e = 1/2 halfway between the
//   inner and outer cones.
// At most kMaxLights (8) lights are GL's: the brightest by E.
#pragma once

#include <vector>

#include "renderer/core/camera.h"
#include "renderer/core/result.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/scene_description.h"

namespace npr {

// `lights` in the viewer's space (SceneObjects::lights); `fileUnits` the length of one of the
// file's units in the viewer's space.
[[nodiscard]] Status applyFileLights(const std::vector<SceneLight>& lights, float fileUnits, const CameraMatrices& camera,
                                     LightingState& state);
// Light 0 back to the viewer's white light and the rest off (after file lights).
void restoreViewerLight(LightingState& state);

}  // namespace npr
