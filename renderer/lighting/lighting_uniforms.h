// Uploads prepared (eye-space) lighting to a program compiled from shaders/lighting.glsl.
#pragma once

#include <epoxy/gl.h>

#include "renderer/lighting/lighting_model.h"

namespace npr {

void uploadLightingUniforms(GLuint program, const PreparedLighting<float>& eyeSpace);

}  // namespace npr
