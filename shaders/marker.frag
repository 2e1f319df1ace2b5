// A filled disc with a dark rim, readable on light and dark palettes alike.
uniform vec3 uColour;
out vec4 fragColor;
void main() {
  float r = length(gl_PointCoord - vec2(0.5)) * 2.0;
  if (r > 1.0) discard;
  fragColor = vec4(r > 0.7 ? vec3(0.0) : uColour, 1.0);
}
