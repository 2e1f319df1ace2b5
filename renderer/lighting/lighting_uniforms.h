// Uploads prepared (eye-space) lighting to a program compiled from shaders/lighting.glsl.
#pragma once

#include "renderer/gl/shader_program.h"
#include "renderer/lighting/lighting_model.h"

namespace npr {

void uploadLightingUniforms(gl::ShaderProgram& program, const PreparedLighting<float>& eyeSpace);

}  // namespace npr
