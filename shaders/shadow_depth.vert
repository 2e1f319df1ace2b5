// Shadow maps: the casters' depth as one light sees them (renderer/shadows/shadow_maps.h).
layout(location = 0) in vec3 aPosition;
uniform mat4 uLightViewProjection;  // model space -> the light's clip space
void main() { gl_Position = uLightViewProjection * vec4(aPosition, 1.0); }
