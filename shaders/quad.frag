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
// ORIENTED: the layer turned per pixel (orientation.glsl), the stroke angle read from the
// buffer the stencil path drew (ORIENT_BUFFER) or fixed.
uniform sampler2DArray uPalette;
uniform ivec2 uLayerSize;
uniform int uLayer;
#include "pattern.glsl"
#ifdef PATTERN_ANCHORED
vec2 layerCoordinate() { return dissolvedCoordinate(patternCoordinate()); }
#else
vec2 layerCoordinate() { return gl_FragCoord.xy; }
#endif
vec4 layerTexel(vec2 u) { return texelFetch(uPalette, ivec3(wrapTexel(u, uLayerSize), uLayer), 0); }
#ifdef ORIENTED
#include "orientation.glsl"
uniform float uLayerAngle;  // the layer's stroke direction (radians; < -10: none)
uniform float uFrameTurn;
#ifdef ORIENT_BUFFER
uniform sampler2D uStrokeAngles;  // (angle, valid) per pixel of the viewport
uniform ivec2 uViewportOrigin;
#else
uniform float uOrientFixed;
#endif
void main() {
#ifdef ORIENT_BUFFER
  vec2 a = texelFetch(uStrokeAngles, ivec2(gl_FragCoord.xy) - uViewportOrigin, 0).rg;
  strokeAngle = a.x;
  strokeValid = a.y > 0.5;
#else
  strokeAngle = uOrientFixed;
  strokeValid = true;
#endif
  vec2 u = layerCoordinate();
  int b0, b1;
  float w;
  if (!orientSteps(uLayerAngle, uFrameTurn, b0, b1, w)) fragColor = layerTexel(u);
  else fragColor = mix(layerTexel(turnedCoordinate(u, b0)), layerTexel(turnedCoordinate(u, b1)), w);
}
#else
void main() { fragColor = layerTexel(layerCoordinate()); }
#endif
#endif
