// Outlines from polygons, after the NPR lecture slides and Raskar and Cohen 1999 ("Image
// Precision Silhouette Edges"), drawn after the front faces so that depth (LEQUAL) hides all
// but the part that sticks out past the silhouette. One method per variant:
//   OUTLINE_EDGES   back faces' edges as screen-space quads twice the line width (core
//                   profiles have no wide lines); the front faces hide their inner half.
//   (OUTLINE_OFFSET needs no geometry stage: outline.vert.)
//   OUTLINE_FATTEN  back faces filled and fattened: each edge pushed outward on screen by the
//                   line width. Raskar and Cohen push each edge in object space by
//                   z sin(a) / (V.N_b), which is what projects to a constant screen width;
//                   pushing on screen gives that width directly, whatever the face's slant.
//   OUTLINE_RIM     (charcoal) front faces near the silhouette, 0 < N.V < uRimLimit,
//                   fattened the same way and drawn with the palette by their tone.
// Triangles crossing the eye plane are dropped (their screen position is undefined).
layout(triangles) in;
#ifdef OUTLINE_EDGES
layout(triangle_strip, max_vertices = 12) out;
#else
layout(triangle_strip, max_vertices = 6) out;
#endif

in vec3 vEye[];

uniform mat4 uProjection;
uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels
uniform float uRimLimit; // OUTLINE_RIM: largest N.V that counts as near the silhouette

#ifdef OUTLINE_RIM
flat out float gTone;  // (1 + V.N) / 3, the charcoal tone of the face
#endif

vec4 clip[3];
vec2 screen[3];  // pixels from the viewport's centre

void emitAt(int i, vec2 s) {
  gl_Position = vec4(s / (0.5 * uViewport) * clip[i].w, clip[i].z, clip[i].w);
  EmitVertex();
}

// The triangle with every edge pushed `width` pixels away from the opposite corner, corners
// bevelled (a hexagon: each corner appears once per edge that meets there). A mitred corner
// would reach far past the line on the thin slivers a silhouette is full of.
void emitFattened(float width) {
  vec2 outward[3];
  for (int e = 0; e < 3; ++e) {
    vec2 a = screen[e], b = screen[(e + 1) % 3], c = screen[(e + 2) % 3];
    vec2 d = b - a;
    float len = length(d);
    vec2 n = len > 1e-6 ? vec2(-d.y, d.x) / len : vec2(0.0);
    if (dot(n, c - a) > 0.0) n = -n;
    outward[e] = n * width;
  }
  // Around the hexagon: P0 = s0+n0, P1 = s1+n0, P2 = s1+n1, P3 = s2+n1, P4 = s2+n2, P5 = s0+n2,
  // emitted as the strip P0 P1 P5 P2 P4 P3 (a convex polygon).
  emitAt(0, screen[0] + outward[0]);
  emitAt(1, screen[1] + outward[0]);
  emitAt(0, screen[0] + outward[2]);
  emitAt(1, screen[1] + outward[1]);
  emitAt(2, screen[2] + outward[2]);
  emitAt(2, screen[2] + outward[1]);
  EndPrimitive();
}

void main() {
  for (int i = 0; i < 3; ++i) {
    clip[i] = uProjection * vec4(vEye[i], 1.0);
    if (clip[i].w <= 1e-6) return;
    screen[i] = clip[i].xy / clip[i].w * (0.5 * uViewport);
  }
  vec3 faceNormal = cross(vEye[1] - vEye[0], vEye[2] - vEye[0]);
  float faceLength = length(faceNormal);
  if (faceLength <= 0.0) return;  // zero area: no side, nothing to outline
  vec3 centre = (vEye[0] + vEye[1] + vEye[2]) / 3.0;
  // N.V with V towards the eye (the eye sits at the origin of eye space).
  float nv = dot(faceNormal / faceLength, -normalize(centre));
#ifdef OUTLINE_RIM
  if (nv <= 0.0 || nv >= uRimLimit) return;
  gTone = (1.0 + nv) / 3.0;
  emitFattened(uWidth);
#else
  if (nv >= 0.0) return;  // front faces are the path's
#if defined(OUTLINE_EDGES)
  float halfWidth = uWidth;  // twice the line: the front faces cover the inner half
  for (int e = 0; e < 3; ++e) {
    int i = e, j = (e + 1) % 3;
    vec2 d = screen[j] - screen[i];
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 perp = vec2(-dir.y, dir.x) * halfWidth;
    vec2 cap = dir * halfWidth;
    emitAt(i, screen[i] - cap - perp);
    emitAt(i, screen[i] - cap + perp);
    emitAt(j, screen[j] + cap - perp);
    emitAt(j, screen[j] + cap + perp);
    EndPrimitive();
  }
#else
  emitFattened(uWidth);
#endif
#endif
}
