// Lighting uniform upload matching the layout declared in shaders/lighting.glsl.
#include "renderer/lighting/lighting_uniforms.h"

#include <vector>


namespace npr {

void uploadLightingUniforms(gl::ShaderProgram& program, const PreparedLighting<float>& p) {
  const glm::vec3 base[2] = {p.base[0], p.base[1]};
  program.setArray("uBase", base, 2);
  if (p.tone != ToneModel::OpenGL) {
    const glm::vec3 cool[2] = {p.cool[0], p.cool[1]}, warm[2] = {p.warm[0], p.warm[1]};
    program.setArray("uCool", cool, 2);
    program.setArray("uWarm", warm, 2);
    program.set("uSplash", glm::vec2(p.splashAlpha, p.splashPower));
  }
  const int n = p.count;
  if (!p.lighting || n == 0) return;
  std::vector<glm::vec3> amb(2 * n), dif(2 * n), spec(2 * n), spotDir(n), att(n);
  std::vector<glm::vec4> pos(n);
  std::vector<float> spotExp(n), spotCos(n);
  for (int i = 0; i < n; ++i) {
    const auto& l = p.lights[i];
    for (int side = 0; side < 2; ++side) {
      amb[side * n + i] = l.ambient[side];
      dif[side * n + i] = l.diffuse[side];
      spec[side * n + i] = l.specular[side];
    }
    pos[i] = glm::vec4(l.position, l.positional ? 1.0f : 0.0f);
    spotDir[i] = l.spotDirection;
    spotExp[i] = l.spot ? l.spotExponent : 0.0f;
    spotCos[i] = l.spot ? l.spotCosCutoff : -2.0f;
    att[i] = glm::vec3(l.k0, l.k1, l.k2);
  }
  // Uniforms a variant compiled out are not found (location -1): setting them is a no-op.
  program.setArray("uLightAmbient", amb.data(), 2 * n);
  program.setArray("uLightDiffuse", dif.data(), 2 * n);
  program.setArray("uLightSpecular", spec.data(), 2 * n);
  program.setArray("uLightPosition", pos.data(), n);
  program.setArray("uSpotDirection", spotDir.data(), n);
  program.setArray("uSpotExponent", spotExp.data(), n);
  program.setArray("uSpotCosCutoff", spotCos.data(), n);
  program.setArray("uAttenuation", att.data(), n);
  program.setArray("uShininess", p.shininess, 2);
}

void uploadMaterialLightingUniforms(gl::ShaderProgram& program, const LightingState& lighting, const glm::mat4& toEyeSpace) {
  // Lit with a white material, the prepared products are the lights' own colours.
  Material white;
  white.ambient = white.diffuse = white.specular = glm::vec4(1.0f);
  white.emission = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  const PreparedLighting<float> p = prepareLighting<float>(lighting.withMaterial(white), toEyeSpace);
  uploadLightingUniforms(program, p);
  program.set("uModelAmbient", glm::vec3(lighting.modelAmbient()));
  if (p.tone != ToneModel::OpenGL) {
    const glm::vec3 cool[2] = {p.coolBase, p.coolBase}, warm[2] = {p.warmBase, p.warmBase};
    program.setArray("uCool", cool, 2);
    program.setArray("uWarm", warm, 2);
    program.set("uToneWeights", glm::vec2(p.toneAlpha, p.toneBeta));
  }
}

}  // namespace npr
