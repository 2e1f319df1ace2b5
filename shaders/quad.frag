// Full-screen passes: the background (QUAD_BACKGROUND) and one palette layer (QUAD_LAYER,
// alpha-blended by the fixed-function blender as in the original stencil algorithm; LAYER_OPAQUE:
// layers stored composited over the background, drawn opaque).
out vec4 fragColor;
#include "pattern.glsl"

#ifdef QUAD_BACKGROUND
#ifdef BACKGROUND_IMAGE
uniform sampler2D uBackground;
uniform ivec2 uBackgroundSize;
uniform float uBackgroundScale;  // texels per pixel: 1 / pattern scale
#else
uniform vec3 uBackgroundColour;
#endif
void main() {
#ifdef BACKGROUND_IMAGE
  fragColor = vec4(texelFetch(uBackground, wrapTexel(framePixel() * uBackgroundScale, uBackgroundSize), 0).rgb, 1.0);
#else
  fragColor = vec4(uBackgroundColour, 1.0);
#endif
}
#endif

#ifdef QUAD_LAYER
// PATTERN_ANCHORED / PATTERN_SCALED: the layer read through the pattern's mapping
// (pattern.glsl; LAYER_SIZES_DIFFER: this palette's layers tile at different sizes).
// ORIENTED: the layer turned per pixel (orientation.glsl), the stroke angle read from the
// buffer the stencil path drew (ORIENT_BUFFER) or fixed.
uniform sampler2DArray uPalette;
uniform ivec2 uLayerSize;
uniform int uLayer;
#ifdef PATTERN_MAPPED
vec3 layerCoordinate() { return mappedCoordinate(); }
vec4 layerTexel(vec3 c) { return mappedTexel(uPalette, c, uLayer, uLayerSize); }
#else
vec3 layerCoordinate() { return vec3(framePixel(), 0.0); }
vec4 layerTexel(vec3 c) { return texelFetch(uPalette, ivec3(wrapTexel(c.xy, uLayerSize), uLayer), 0); }
#endif
#ifdef ORIENTED
#include "orientation.glsl"
uniform float uLayerAngle;  // the layer's stroke direction (radians; < -10: none)
uniform float uFrameTurn;
#ifdef ORIENT_BUFFER
uniform sampler2D uStrokeAngles;  // (angle, valid) per pixel of the viewport
#ifndef PATTERN_OBJECT_BUFFER
uniform ivec2 uViewportOrigin;  // (declared by pattern.glsl for its own buffer)
#endif
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
  vec3 c = layerCoordinate();
  int b0, b1;
  float w;
  // Branch-free, as palette.glsl's: where no stroke angle is set the steps are 0 (no turn).
  orientSteps(uLayerAngle, uFrameTurn, b0, b1, w);
  fragColor = mix(layerTexel(vec3(turnedCoordinate(c.xy, b0), c.z)), layerTexel(vec3(turnedCoordinate(c.xy, b1), c.z)), w);
#ifdef LAYER_OPAQUE
  fragColor.a = 1.0;
#endif
}
#else
void main() {
  fragColor = layerTexel(layerCoordinate());
#ifdef LAYER_OPAQUE
  fragColor.a = 1.0;  // composited layers: their alpha is the tone threshold map (palette/tone_thresholds.h)
#endif
}
#endif
#endif
