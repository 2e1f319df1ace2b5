// Painterly brush strokes (strokes/brush_stroke_pass.h): one instanced quad per stroke
// particle, sized in pixels, turned along the direction field projected to the screen (across
// the light's gradient where the field has no direction), lit at the particle with the scene's
// lighting; near the silhouette it turns to follow the contour. Strokes turned away from the eye fade out over the last few degrees, and strokes
// beyond the fraction kept at this distance fade out over a band of ranks: nothing pops. The
// quad is pulled towards the eye along its ray by half its size (the ray keeps where it
// projects), so the surface it sits on does not cut it while nearer surfaces still hide it.
#include "lighting.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aDirection;
layout(location = 3) in vec2 aRankSeed;

uniform mat4 uModelView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;
uniform vec2 uViewport;      // pixels
uniform vec2 uStrokeSize;    // length, width in pixels
uniform float uKeepDepth;    // eye depth at which every stroke is drawn; beyond it (d0 / d)^2 of them
uniform float uFadeBand;     // relative width of the ranks over which a thinned stroke fades (0: cut)
uniform vec3 uLightEye;      // the first light's direction or position (w in uLightPositional)
uniform float uLightPositional;

out vec2 vUv;        // along, across the stroke in [0,1]
flat out vec3 vLit;  // the lit colour at the particle
flat out float vAlpha;
flat out float vSeed;

void main() {
  vec3 eye = (uModelView * vec4(aPosition, 1.0)).xyz;
  vec3 n = normalize(uNormalMatrix * aNormal);
  vec3 toEye = normalize(-eye);
  float facing = dot(n, toEye);
  float depth = max(-eye.z, 1e-4);
  float keep = clamp(uKeepDepth * uKeepDepth / (depth * depth), 0.0, 1.0);
  // Faded over ranks [k, k (1 + band)], k chosen so that the strokes drawn still add up to
  // `keep`: a band relative to the kept fraction, or far away the band would outnumber it.
  float k = keep / (1.0 + 0.5 * uFadeBand);
  float kept = uFadeBand > 0.0 ? clamp((k * (1.0 + uFadeBand) - aRankSeed.x) / (k * uFadeBand), 0.0, 1.0) : float(aRankSeed.x < keep);
  vAlpha = kept * smoothstep(0.0, 0.12, facing);
  vSeed = aRankSeed.y;
  int corner = gl_VertexID;
  vUv = vec2(corner >= 2 ? 1.0 : 0.0, (corner % 2 == 0) ? 0.0 : 1.0);
  if (vAlpha <= 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
    vLit = vec3(0.0);
    return;
  }
  vLit = shadeGL(eye, n, false);
  // The stroke's direction on screen: the field's, else across the light's gradient (along
  // the isophote: the tangent perpendicular to the light's direction in the surface).
  vec3 dir = uNormalMatrix * aDirection;
  if (dot(dir, dir) < 1e-8) {
    vec3 l = uLightPositional > 0.5 ? normalize(uLightEye - eye) : normalize(uLightEye);
    dir = cross(n, l);
    if (dot(dir, dir) < 1e-8) dir = cross(n, vec3(0.0, 1.0, 0.0));
  }
  vec4 clip = uProjection * vec4(eye, 1.0);
  vec4 ahead = uProjection * vec4(eye + normalize(dir) * 0.01 * depth, 1.0);
  vec2 halfViewport = 0.5 * uViewport;
  vec2 s0 = clip.xy / clip.w * halfViewport;
  vec2 d = ahead.xy / ahead.w * halfViewport - s0;
  float len = length(d);
  vec2 along = len > 1e-5 ? d / len : vec2(1.0, 0.0);
  // Near the silhouette the stroke turns to follow the contour (perpendicular to the normal on
  // screen), as a painter's last strokes do: one turned across it would hang off the form by
  // half its length.
  vec2 nScreen = n.xy;
  if (dot(nScreen, nScreen) > 1e-8) {
    vec2 contour = normalize(vec2(-nScreen.y, nScreen.x));
    contour *= dot(contour, along) < 0.0 ? -1.0 : 1.0;
    along = normalize(mix(along, contour, 1.0 - smoothstep(0.15, 0.5, facing)) + vec2(1e-6, 0.0));
  }
  // Jitter: a few degrees of turn and a fifth of the size, from the particle's seed.
  float turn = (aRankSeed.y - 0.5) * 0.35;
  along = mat2(cos(turn), sin(turn), -sin(turn), cos(turn)) * along;
  vec2 across = vec2(-along.y, along.x);
  vec2 size = uStrokeSize * (0.8 + 0.4 * fract(aRankSeed.y * 7.31));
  vec2 offset = along * (vUv.x - 0.5) * size.x + across * (vUv.y - 0.5) * size.y;
  // Pulled along the ray by half the stroke's length in eye units at this depth.
  float pixelToEye = depth * 2.0 / (uProjection[1][1] * uViewport.y);
  vec3 pulled = eye + toEye * min(0.5 * size.x * pixelToEye, 0.5 * depth);
  vec4 p = uProjection * vec4(pulled, 1.0);
  gl_Position = vec4((s0 + offset) / halfViewport * p.w, p.z, p.w);
}
