// Full-screen passes: the background (QUAD_BACKGROUND) and one palette layer (QUAD_LAYER,
// alpha-blended by the fixed-function blender as in the original stencil algorithm).
out vec4 fragColor;

#ifdef QUAD_BACKGROUND
#ifdef BACKGROUND_IMAGE
uniform sampler2D uBackground;
uniform ivec2 uBackgroundSize;
#else
uniform vec3 uBackgroundColour;
#endif
void main() {
#ifdef BACKGROUND_IMAGE
  fragColor = vec4(texelFetch(uBackground, ivec2(gl_FragCoord.xy) % uBackgroundSize, 0).rgb, 1.0);
#else
  fragColor = vec4(uBackgroundColour, 1.0);
#endif
}
#endif

#ifdef QUAD_LAYER
uniform sampler2DArray uPalette;
uniform ivec2 uLayerSize;
uniform int uLayer;
#ifdef PATTERN_ANCHORED
#include "pattern.glsl"
void main() {
  vec2 u = dissolvedCoordinate(patternCoordinate());
  fragColor = texelFetch(uPalette, ivec3(wrapTexel(u, uLayerSize), uLayer), 0);
}
#else
void main() {
  fragColor = texelFetch(uPalette, ivec3(ivec2(gl_FragCoord.xy) % uLayerSize, uLayer), 0);
}
#endif
#endif
