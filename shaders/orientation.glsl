// Hatching orientation (RenderSettings::orient): the stroke angle this pixel wants on screen,
// and palette lookups turned so that an entry's own stroke direction runs along it.
// The turn is quantised to ORIENT_BINS steps over 180 degrees (strokes are lines: a half turn
// maps them onto themselves) and the two nearest steps are blended: within a step the lookup is
// a rigid rotation, so strokes stay straight where the wanted angle varies across a surface.
// Mesh passes say where the angle comes from (ORIENT_FIELD: the interpolated direction field;
// ORIENT_LIGHT: the light's direction laid into the surface, the way its shading changes
// fastest; ORIENT_FIXED: a uniform); the stencil path's layer quads read it from a buffer.
#ifndef ORIENTATION_GLSL
#define ORIENTATION_GLSL

// Set by the pass before the palette is sampled; strokeValid false leaves lookups unturned.
float strokeAngle = 0.0;
bool strokeValid = false;

#ifdef ORIENT_BINS
uniform vec2 uBinRotation[ORIENT_BINS];  // (cos, sin) of step b's turn, b * 180 / ORIENT_BINS degrees

// Texture coordinate u turned by step b (sampling at R(-a) u shows the texture turned by +a).
vec2 turnedCoordinate(vec2 u, int b) {
  vec2 cs = uBinRotation[b];
  return vec2(cs.x * u.x + cs.y * u.y, -cs.y * u.x + cs.x * u.y);
}

// The two steps to blend (weight w of b1) for an entry whose strokes run at `entryAngle` in
// its texture (radians; below -10: no dominant direction), the texture's frame itself turned by
// `frameTurn` on screen (the anchored pattern's rotation). False: sample unturned (the steps
// are then both 0, no turn, so a caller may draw the two lookups regardless).
bool orientSteps(float entryAngle, float frameTurn, out int b0, out int b1, out float w) {
  b0 = 0;
  b1 = 0;
  w = 0.0;
  if (!strokeValid || entryAngle < -10.0) return false;
  const float K = float(ORIENT_BINS);
  float t = (strokeAngle - frameTurn - entryAngle) * (K / 3.14159265);
  t -= K * floor(t / K);
  float f = min(floor(t), K - 1.0);
  b0 = int(f);
  b1 = b0 + 1 == ORIENT_BINS ? 0 : b0 + 1;
  w = clamp(t - f, 0.0, 1.0);
  return true;
}
#endif

#if defined(ORIENT_FIELD) || defined(ORIENT_LIGHT)
uniform vec2 uViewportSize;
// The unit screen direction of a tangent at a point, from the point's clip position `c` and
// the tangent's `dc` (projected with w = 0): the derivative of the projection, or zero where the
// tangent points along the view ray (or is zero) and has no direction on screen. Computed per
// vertex and interpolated: two components to interpolate instead of the six a per-pixel
// projection would need (position and direction), which on a CPU rasterizer is most of the cost
// on large meshes; the vertex's own gl_Position is `c`.
vec2 screenDirectionClip(vec4 c, vec4 dc) {
  vec2 s = (dc.xy * c.w - c.xy * dc.w) * uViewportSize;
  vec2 scale = (abs(dc.xy * c.w) + abs(c.xy * dc.w)) * uViewportSize;
  return dot(s, s) > 1e-6 * dot(scale, scale) ? normalize(s) : vec2(0.0);
}
// This pixel's stroke angle from the interpolated direction.
void setStrokeFromDirection(vec2 d) {
  strokeValid = dot(d, d) > 1e-6;
  strokeAngle = strokeValid ? atan(d.y, d.x) : 0.0;
}
#endif
#ifdef ORIENT_LIGHT
uniform vec4 uOrientLight;  // the first enabled light, eye space (w = 0: directional)
vec3 lightAcrossSurface(vec3 p, vec3 n) {
  vec3 l = uOrientLight.w == 0.0 ? uOrientLight.xyz : uOrientLight.xyz - p;
  vec3 nn = normalize(n);
  return l - dot(l, nn) * nn;
}
#endif
#ifdef ORIENT_FIXED
uniform float uOrientFixed;  // radians
#endif

#endif
