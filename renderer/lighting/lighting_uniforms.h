// Uploads prepared (eye-space) lighting to a program compiled from shaders/lighting.glsl.
#pragma once

#include "renderer/gl/shader_program.h"
#include "renderer/lighting/lighting_model.h"

namespace npr {

void uploadLightingUniforms(gl::ShaderProgram& program, const PreparedLighting<float>& eyeSpace);
// For a MATERIALS program: the lights' own colours (the material comes from the table), the
// light-model ambient, and the tone parameters without a material.
void uploadMaterialLightingUniforms(gl::ShaderProgram& program, const LightingState& lighting, const glm::mat4& toEyeSpace);

}  // namespace npr
