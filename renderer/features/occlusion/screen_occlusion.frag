// Screen-space ambient occlusion (renderer/shadows/screen_occlusion_pass.h), two passes of a
// full-screen triangle:
//  - (default) from the frame's eye-space normals and depth (at half the frame's resolution:
//    occlusion varies slowly), the share of KERNEL_SIZE points in
//    the hemisphere of radius uRadius over each pixel's surface point that no nearer surface
//    covers, cosine-weighted like the bake (points lie nearer the normal more often), the
//    kernel turned per pixel by one of 16 angles in a 4x4 tile;
//  - BLUR: the 4x4 mean that cancels the tile's pattern, over pixels at a similar depth only,
//    so occlusion does not bleed across silhouettes; written with the pixel's depth, which the
//    frame's read (mesh.frag) uses to take its value from texels of its own surface.
// 1 is open, 0 enclosed; pixels without a surface are 1.
uniform sampler2D uDepth;
uniform ivec2 uOrigin;  // the viewport's corner in the framebuffer
out vec4 fragColor;

#ifdef BLUR
uniform sampler2D uOcclusion;
uniform vec2 uProjection;  // P[2][2], P[3][2]: to linearise depth

float linearDepth(ivec2 p) {
  float z = texelFetch(uDepth, p, 0).r * 2.0 - 1.0;
  return abs(uProjection.y / (z + uProjection.x));
}

void main() {
  ivec2 c = ivec2(gl_FragCoord.xy) - uOrigin;
  ivec2 size = textureSize(uDepth, 0);
  if (texelFetch(uDepth, c, 0).r >= 1.0) {
    fragColor = vec4(1.0, 1e30, 0.0, 1.0);
    return;
  }
  float d0 = linearDepth(c);
  float sum = 0.0, weight = 0.0;
  for (int j = -2; j < 2; ++j)
    for (int i = -2; i < 2; ++i) {
      ivec2 p = clamp(c + ivec2(i, j), ivec2(0), size - 1);
      float w = abs(linearDepth(p) - d0) < 0.05 * d0 ? 1.0 : 0.0;
      sum += w * texelFetch(uOcclusion, p, 0).r;
      weight += w;
    }
  // Depth beside it: the frame's read weighs the texels around a pixel by their depth.
  fragColor = vec4(weight > 0.0 ? sum / weight : 1.0, d0, 0.0, 1.0);
}
#else
uniform sampler2D uNormals;  // eye-space normals; alpha 0 where no surface
uniform vec4 uProjectionXY;  // P[0][0], P[1][1], P[2][0], P[2][1] (a perspective projection)
uniform vec2 uProjection;    // P[2][2], P[3][2]
uniform vec2 uSize;          // the target's size in pixels
uniform float uRadius;       // eye units
uniform vec3 uKernel[KERNEL_SIZE];  // in the unit hemisphere around +z

float eyeZ(float depth) { return -uProjection.y / (depth * 2.0 - 1.0 + uProjection.x); }

void main() {
  ivec2 c = ivec2(gl_FragCoord.xy) - uOrigin;
  vec4 nt = texelFetch(uNormals, c, 0);
  float depth = texelFetch(uDepth, c, 0).r;
  if (nt.a == 0.0 || depth >= 1.0) {
    fragColor = vec4(1.0);
    return;
  }
  float z = eyeZ(depth);
  vec2 ndc = (vec2(c) + 0.5) / uSize * 2.0 - 1.0;
  vec3 pos = vec3((ndc * -z - uProjectionXY.zw * z) / uProjectionXY.xy, z);
  vec3 n = normalize(nt.xyz + vec3(1e-9));
  if (dot(n, -pos) < 0.0) n = -n;  // a back face seen: the side facing the eye
  // The tile's angle: 16 evenly spread, in an order that puts far-apart angles next to each other.
  int k = (c.x & 3) + 4 * (c.y & 3);
  float angle = float((k * 7) & 15) * (6.2831853 / 16.0);
  vec3 r = vec3(cos(angle), sin(angle), 0.0);
  vec3 t = r - n * dot(r, n);
  if (dot(t, t) < 1e-6) t = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) - n * n.x : vec3(0.0, 1.0, 0.0) - n * n.y;
  t = normalize(t);
  mat3 tbn = mat3(t, cross(n, t), n) * uRadius;
  float covered = 0.0;
  for (int i = 0; i < KERNEL_SIZE; ++i) {
    vec3 s = pos + tbn * uKernel[i];
    if (s.z >= 0.0) continue;  // behind the eye: nothing known covers it
    vec2 q = ((uProjectionXY.xy * s.xy + uProjectionXY.zw * s.z) / -s.z * 0.5 + 0.5) * uSize;
    if (any(lessThan(q, vec2(0.0))) || any(greaterThanEqual(q, uSize))) continue;  // off screen
    float sceneDepth = texelFetch(uDepth, ivec2(q), 0).r;
    if (sceneDepth >= 1.0) continue;
    float sceneZ = eyeZ(sceneDepth);
    if (sceneZ <= s.z) continue;  // the surface there is behind the point: it is open
    // The surface point hiding it: an occluder only if it rises above this pixel's tangent
    // plane (the pixel's own plane, met again through the depth buffer's texels, never counts:
    // at grazing views its depth differs from the point's by the slope times a texel) and
    // lies within about the radius (a surface far in front does not enclose this one).
    vec2 qc = (floor(q) + 0.5) / uSize * 2.0 - 1.0;
    vec3 d = vec3((qc * -sceneZ - uProjectionXY.zw * sceneZ) / uProjectionXY.xy, sceneZ) - pos;
    if (dot(d, n) > 0.05 * uRadius) covered += 1.0 - smoothstep(uRadius, 2.0 * uRadius, length(d));
  }
  fragColor = vec4(1.0 - covered / float(KERNEL_SIZE));
}
#endif
