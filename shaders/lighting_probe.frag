// See lighting_probe.vert.
#include "lighting.glsl"
flat in vec3 vPosition;
flat in vec3 vNormal;
flat in float vBack;
out vec4 fragColor;
void main() { fragColor = vec4(shadeGL(vPosition, vNormal, vBack > 0.5), 1.0); }
