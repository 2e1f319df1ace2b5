// Shadow maps: the casters' depth as one light sees them (renderer/shadows/shadow_maps.h).
// ALPHA_COVERAGE: a see-through caster, whose material and map coordinates reach the fragment
// stage (coverage.glsl).
layout(location = 0) in vec3 aPosition;
uniform mat4 uLightViewProjection;  // model space -> the light's clip space
#ifdef ALPHA_COVERAGE
layout(location = 3) in vec2 aTexcoord;
layout(location = 4) in uint aMaterial;
out vec2 vTexcoord;
flat out uint vMaterial;
#endif
void main() {
  gl_Position = uLightViewProjection * vec4(aPosition, 1.0);
#ifdef ALPHA_COVERAGE
  vTexcoord = aTexcoord;
  vMaterial = aMaterial;
#endif
}
