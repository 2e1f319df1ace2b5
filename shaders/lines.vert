// Feature lines as screen-aligned quads (wide GL lines are not core): one instance per edge,
// four strip vertices, widened in pixels and pulled slightly towards the eye so the depth
// test against the model removes hidden lines without z-fighting on their own faces.
// SKETCHY draws each edge as three jittered sub-strokes whose jitter is a hash of the edge's
// endpoints: stable from frame to frame. Each sub-stroke tapers to a point at both ends and its
// pressure (darkness and width) changes along it between two hashed values, as a pencil's does. DEPTH_FALLOFF thins lines with distance;
// BY_CURVATURE widens them where the surface curves more than the mesh's median (a line set's curvature=GAIN).
// Edges come chained into strokes (renderer/lines/line_chains.h): DASHED runs the dashes along
// the stroke's parameter, kept from frame to frame, so they neither restart at each edge nor
// crawl as the view turns; TAPERED narrows the stroke to points at its chain's ends; TEXTURED
// stretches a texture along it. All are in pixels at the object's centre (uParamPixels per
// object unit).
#ifdef TONE_COLOUR
// colour=tone: lit at the line with the surface's normal, as the painterly strokes are.
#include "lighting.glsl"
uniform mat4 uModelView;
uniform mat3 uNormalMatrix;
layout(location = 9) in vec3 aNormal;
out vec3 vLit;
#endif
layout(location = 0) in vec3 aStart;
layout(location = 1) in vec3 aEnd;
layout(location = 2) in float aKind;
layout(location = 3) in vec2 aParam;   // the stroke's parameter at the start and the end
layout(location = 4) in vec2 aArc;     // the distance from the chain's start to them
layout(location = 5) in float aLength; // the chain's length; negative: a closed loop
layout(location = 6) in uvec2 aMaterials;  // the faces' materials on either side
layout(location = 7) in vec2 aCurvature;  // the surface's at the start and the end (0: not known)
layout(location = 8) in float aInk;       // how much of its ink the line draws (suggestive contours fade in)
layout(location = 10) in vec4 aBefore;   // the chain's vertex before aStart (w 0: none)
layout(location = 11) in vec4 aAfter;    // ... and after aEnd

uniform mat4 uModelViewProjection;
uniform vec2 uViewport;    // pixels
uniform float uWidth;      // pixels
uniform vec3 uColours[EDGE_KINDS];  // silhouette, crease, boundary, material, intersection, suggestive (EdgeKind)
uniform float uFalloffDepth;
// Intersection lines lie in a valley: the two surfaces come towards the eye on both sides, so
// the quad's own pixels fail the depth test against them. Their ends are moved towards the eye
// (along the view ray: the picture does not move) by uValleyPixels pixels' worth of depth.
// uEye: the eye in the lines' space (w 1), or its direction for an orthographic camera (w 0);
// a pixel at distance d is uPixelScale.x * d + uPixelScale.y across.
uniform float uValleyPixels;
uniform vec4 uEye;
uniform vec2 uPixelScale;
uniform float uParamPixels;
#ifdef BY_CURVATURE
uniform float uCurvatureGain, uCurvatureReference;
#endif
#ifdef BY_MATERIAL
// BY_MATERIAL: a line set selecting materials draws only lines on a face of one of them.
uniform uint uMaterialMask[8];  // bit m: material m is taken (0xFFFF: none)
bool taken(uint m) { return m < 256u && (uMaterialMask[m >> 5] & (1u << (m & 31u))) != 0u; }
#endif

#ifdef OCCLUSION_LIMIT
// Hidden parts limited by occlusion level (a set's occlusion=LEVEL, lines/occlusion_layers.h):
// each end of the edge is tested against the limit layer, the surface one more than LEVEL
// surfaces would put in front of it, and the fragment stage leaves out the half beyond.
uniform sampler2D uOcclusionLimit;  // window depth of the limit layer over the viewport (1: none)
uniform ivec2 uOcclusionSize;       // the viewport's size
uniform vec3 uDepthMap;             // view_distance.glsl's map for this camera
uniform float uOcclusionTolerance;  // eye units: a line on the limit surface itself is not behind it
out float vBeyondLimit;
#include "view_distance.glsl"
// Whether the point at clip position `p` (pixel `s` from the viewport's centre) lies behind the
// limit layer. The farthest of the layer within a pixel: an edge is where the faces meeting
// there are farthest, and a pixel's centre beside it falls on them, nearer by their slope.
float beyondLimit(vec4 p, vec2 s) {
  ivec2 at = ivec2(floor(s + 0.5 * vec2(uOcclusionSize)));
  float limit = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) limit = max(limit, texelFetch(uOcclusionLimit, clamp(at + ivec2(dx, dy), ivec2(0), uOcclusionSize - 1), 0).r);
  if (limit >= 1.0) return 0.0;
  return viewDistance(0.5 * p.z / p.w + 0.5, uDepthMap) > viewDistance(limit, uDepthMap) + uOcclusionTolerance ? 1.0 : 0.0;
}
#endif
out vec3 vColour;
flat out float vInk;
// At its joints (x: the start's, y: the end's): pixels on this segment's side of the cut
// (negative: the neighbour's side), inside this segment from the joint (negative: its cap), and
// along and across the neighbour from the joint, with the neighbour's length in pixels.
noperspective out vec2 vJoint, vJointAlong, vJointAcross, vJointInside;
flat out vec2 vNeighbourLength;
// A dot (a segment of no length: a file's point): drawn round, vDotAlong pixels from its centre
// along the quad as vAcross is across it.
flat out float vDot;
noperspective out float vDotAlong;
out float vAcross;  // pixels from the line's centre
flat out float vHalfWidth;
#ifdef DASHED
out float vDash;           // the stroke's parameter in pixels, for the dashes
#endif
#if defined(TAPERED) || defined(TEXTURED)
out float vArc;            // pixels from the chain's start
flat out float vChain;     // the chain's length in pixels
#endif
#ifdef TEXTURED
flat out float vWay;       // 1 where the segment runs along its chain, -1 against: the texture's side
#endif
#ifdef SKETCHY
out float vAlong;          // pixels from the stroke's start (its cap included)
flat out float vLength;    // the stroke's length in pixels
flat out vec2 vPressure;   // at its start and end: how hard the pencil pressed (0.45..1)
#endif

uint hashBits(uint x) {
  x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
  return x;
}
float hash01(uint x) { return float(hashBits(x) & 0xFFFFu) / 65535.0; }

vec2 unitOr(vec2 d, vec2 otherwise) {
  float len = length(d);
  return len > 1e-4 ? d / len : otherwise;
}

// Where a joint at `at` (pixels) cuts this segment's quad: its far end at `own`, the
// neighbour's at `other` (clip space, w 0: no neighbour). The cut runs along the bisector of
// the angle the two make at the joint; the neighbour computes the same line from the same
// numbers with the sides swapped. Where a cap (the half width a quad reaches past its end)
// overlaps the neighbour's quad, lines.frag leaves the part on the neighbour's side to the
// neighbour, so a pixel there is inked once (a partial coverage blended twice darkened every
// joint). A pixel only one quad covers stays its own: the cut never opens a gap. `cut`: the
// normal pointing into this segment, zero for no cut (no neighbour, one behind the eye, or a
// hairpin, where the two run the same way).
struct Joint {
  vec2 cut, along;  // the cut's normal; the unit from the joint to the neighbour's far end
  float length;     // the neighbour's, pixels
};
Joint jointCut(vec2 at, vec2 own, vec4 other, vec2 half_) {
  Joint j = Joint(vec2(0.0), vec2(0.0), 0.0);
  if (other.w <= 0.0) return j;
  vec2 far = other.xy / other.w * half_;
  vec2 u = unitOr(own - at, vec2(0.0)), v = unitOr(far - at, vec2(0.0));
  vec2 n = u - v;
  if (dot(u, u) > 0.5 && dot(v, v) > 0.5 && dot(n, n) > 0.01) j = Joint(n, v, length(far - at));
  return j;
}

vec3 towardsEye(vec3 p) {
  vec3 toEye = uEye.w > 0.5 ? uEye.xyz - p : uEye.xyz;
  float d = length(toEye);
  if (d <= 0.0) return p;
  float pixel = uPixelScale.x * d + uPixelScale.y;
  return p + toEye / d * min(uValleyPixels * pixel, 0.5 * d);
}

void main() {
  vec3 start = aStart, end_ = aEnd;
  if (int(aKind + 0.5) == 4 && uValleyPixels > 0.0) {  // EdgeKind::Intersection
    start = towardsEye(aStart);
    end_ = towardsEye(aEnd);
  }
  vec4 p0 = uModelViewProjection * vec4(start, 1.0);
  vec4 p1 = uModelViewProjection * vec4(end_, 1.0);
  vColour = uColours[int(aKind + 0.5)];
  vInk = aInk;
  float width = uWidth;
  bool isDot = aStart == aEnd;
  vDot = isDot ? 1.0 : 0.0;
  if (isDot) width = max(2.5 * width, 3.0);  // markDotDiameter (lines/line_pass.h)
#ifdef DEPTH_FALLOFF
  width *= clamp(uFalloffDepth / max(0.5 * (p0.w + p1.w), 1e-6), 0.35, 1.6);
#endif
#ifdef BY_CURVATURE
  // Heavier where the surface curves more than the mesh's median (lighter, gain < 0); lines
  // with no curvature of their own (intersections, suggestive contours) keep the width.
  float curvature = 0.5 * (aCurvature.x + aCurvature.y);
  if (curvature > 0.0) width *= clamp(pow(curvature / max(uCurvatureReference, 1e-6), uCurvatureGain), 0.25, 4.0);
#endif
  bool drop = p0.w <= 0.0 || p1.w <= 0.0;  // crosses the eye plane
#ifdef BY_MATERIAL
  drop = drop || !(taken(aMaterials.x) || taken(aMaterials.y));
#endif
  if (drop) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    vJoint = vJointAlong = vJointAcross = vJointInside = vNeighbourLength = vec2(0.0);
    vDotAlong = 0.0;
    vAcross = 0.0;
    vHalfWidth = 0.0;
    return;
  }
  vec2 half_ = 0.5 * uViewport;
  vec2 s0 = p0.xy / p0.w * half_, s1 = p1.xy / p1.w * half_;
#ifndef SKETCHY
  // The joints' cuts, before the ends move: both segments at a joint must see the same points.
  bool pulled = int(aKind + 0.5) == 4 && uValleyPixels > 0.0;
  vec4 before = aBefore.w > 0.5 ? uModelViewProjection * vec4(pulled ? towardsEye(aBefore.xyz) : aBefore.xyz, 1.0) : vec4(0.0);
  vec4 after = aAfter.w > 0.5 ? uModelViewProjection * vec4(pulled ? towardsEye(aAfter.xyz) : aAfter.xyz, 1.0) : vec4(0.0);
  Joint cut0 = jointCut(s0, s1, before, half_), cut1 = jointCut(s1, s0, after, half_);
#endif
#ifdef SKETCHY
  uint seed = floatBitsToUint(aStart.x) ^ hashBits(floatBitsToUint(aStart.y) ^ hashBits(floatBitsToUint(aStart.z))) ^
              hashBits(floatBitsToUint(aEnd.x) + floatBitsToUint(aEnd.y) * 3u + floatBitsToUint(aEnd.z) * 7u) ^
              hashBits(uint(gl_InstanceID % 3) + 11u);
  vec2 d0 = s1 - s0;
  float len0 = length(d0);
  vec2 dir0 = len0 > 1e-4 ? d0 / len0 : vec2(1.0, 0.0);
  vec2 nrm0 = vec2(-dir0.y, dir0.x);
  float amp = 1.0 + 0.5 * width;
  s0 += nrm0 * (hash01(seed) - 0.5) * amp + dir0 * (hash01(seed + 1u) - 0.6) * 2.0 * amp;
  s1 += nrm0 * (hash01(seed + 2u) - 0.5) * amp + dir0 * (hash01(seed + 3u) - 0.4) * 2.0 * amp;
  width *= 0.75;
  vPressure = vec2(0.45) + 0.55 * vec2(hash01(seed + 4u), hash01(seed + 5u));
#endif
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  vec2 perp = vec2(-dir.y, dir.x);
  bool end = gl_VertexID >= 2;
  float side = (gl_VertexID % 2 == 0) ? -1.0 : 1.0;
  vHalfWidth = 0.5 * width + 0.5;  // half a pixel more for the antialiased rim
  vec4 p = end ? p1 : p0;
  // A dot's quad reaches its rim along as well as across.
  float reach = isDot ? vHalfWidth : 0.5 * width;
  vec2 s = (end ? s1 : s0) + perp * side * vHalfWidth + dir * (end ? 1.0 : -1.0) * reach;
  vDotAlong = (end ? 1.0 : -1.0) * reach;
  vAcross = side * vHalfWidth;
#ifdef SKETCHY
  vJoint = vec2(1.0);  // sketchy strokes overlap as a pencil's do
  vJointAlong = vJointAcross = vJointInside = vNeighbourLength = vec2(0.0);
#else
  vJoint = vec2(dot(s - s0, cut0.cut), dot(s - s1, cut1.cut)) + vec2(cut0.length > 0.0 ? 0.0 : 1.0, cut1.length > 0.0 ? 0.0 : 1.0);
  vJointAlong = vec2(dot(s - s0, cut0.along), dot(s - s1, cut1.along));
  vJointAcross = vec2(dot(s - s0, vec2(-cut0.along.y, cut0.along.x)), dot(s - s1, vec2(-cut1.along.y, cut1.along.x)));
  vNeighbourLength = vec2(cut0.length, cut1.length);
  vJointInside = vec2(dot(s - s0, dir), dot(s1 - s, dir));
#endif
  // The quad's caps reach half a width past the segment's ends, along the parameter's way.
#ifdef DASHED
  float dashWay = aParam.y >= aParam.x ? 1.0 : -1.0;
  vDash = (end ? aParam.y : aParam.x) * uParamPixels + (end ? 0.5 : -0.5) * width * dashWay;
#endif
#if defined(TAPERED) || defined(TEXTURED)
  vArc = (end ? aArc.y : aArc.x) * uParamPixels + (end ? 0.5 : -0.5) * width * (aArc.y >= aArc.x ? 1.0 : -1.0);
  vChain = aLength * uParamPixels;
#endif
#ifdef TEXTURED
  vWay = aArc.y >= aArc.x ? 1.0 : -1.0;
#endif
#ifdef SKETCHY
  vLength = len + width;
  vAlong = end ? vLength : 0.0;
#endif
  gl_Position = vec4(s / half_ * p.w, p.z - 3e-4 * p.w, p.w);
#ifdef OCCLUSION_LIMIT
  vBeyondLimit = beyondLimit(p, end ? s1 : s0);
#endif
#ifdef TONE_COLOUR
  vec3 eyePosition = (uModelView * vec4(end ? end_ : start, 1.0)).xyz;
  vec3 n = uNormalMatrix * aNormal;
  // A line with no normal of its own (none known) faces the eye.
  n = dot(n, n) > 1e-12 ? normalize(n) : normalize(-eyePosition);
  vLit = shadeGL(eyePosition, n, false);
#endif
}
