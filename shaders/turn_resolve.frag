// The turned palette lookups of a mesh pass drawn with DEFER_TURN, once per pixel: on meshes
// whose triangles cover a pixel or less, a mesh pass shades a block of pixels for each
// triangle, so the turn (the angle's steps and two lookups) done there is paid many times
// over; the mesh pass writes each pixel's stroke angle and entry instead
// (passes/turn_resolve_pass.h) and this draws the entry's texel turned by that angle, with the
// same palette.glsl as the mesh passes, only where the stencil marks a pixel it wrote.
#include "palette.glsl"

// (stroke angle, entry + 1, negative where there is no stroke angle; with RESOLVE_BLEND, the
// smooth path's, also the second entry and its weight)
uniform sampler2D uTurnBuffer;
uniform ivec2 uBufferOrigin;  // the framebuffer pixel the buffer's texel (0, 0) holds
out vec4 fragColor;

void main() {
  vec4 t = texelFetch(uTurnBuffer, ivec2(gl_FragCoord.xy) - uBufferOrigin, 0);
  strokeAngle = t.x;
  strokeValid = t.y > 0.0;
#ifdef RESOLVE_BLEND
  vec3 c = toneBetween(int(abs(t.y)) - 1, int(t.z), t.w);
#else
  vec3 c = paletteColour(int(abs(t.y)) - 1);
#endif
  fragColor = vec4(c, 1.0);
}
