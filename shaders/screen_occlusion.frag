// Screen-space ambient occlusion (renderer/shadows/screen_occlusion_pass.h), two passes of a
// full-screen triangle:
//  - (default) from the frame's eye-space normals and depth, the share of KERNEL_SIZE points in
//    the hemisphere of radius uRadius over each pixel's surface point that no nearer surface
//    covers, cosine-weighted like the bake (points lie nearer the normal more often), the
//    kernel turned per pixel by one of 16 angles in a 4x4 tile;
//  - BLUR: the 4x4 mean that cancels the tile's pattern, over pixels at a similar depth only,
//    so occlusion does not bleed across silhouettes.
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
    fragColor = vec4(1.0);
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
  fragColor = vec4(weight > 0.0 ? sum / weight : 1.0);
}
#else
uniform sampler2D uNormals;  // eye-space normals; alpha 0 where no surface
uniform mat4 uProjectionMatrix;
uniform mat4 uInverseProjection;
uniform vec2 uSize;          // the viewport's size in pixels
uniform float uRadius;       // eye units
uniform vec3 uKernel[KERNEL_SIZE];  // in the unit hemisphere around +z

vec3 eyePosition(vec2 pixel, float depth) {
  vec4 ndc = vec4(pixel / uSize * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  vec4 eye = uInverseProjection * ndc;
  return eye.xyz / eye.w;
}

void main() {
  ivec2 c = ivec2(gl_FragCoord.xy) - uOrigin;
  vec4 nt = texelFetch(uNormals, c, 0);
  float depth = texelFetch(uDepth, c, 0).r;
  if (nt.a == 0.0 || depth >= 1.0) {
    fragColor = vec4(1.0);
    return;
  }
  vec3 pos = eyePosition(vec2(c) + 0.5, depth);
  vec3 n = normalize(nt.xyz + vec3(1e-9));
  if (dot(n, -pos) < 0.0) n = -n;  // a back face seen: the side facing the eye
  // The tile's angle: 16 evenly spread, in an order that puts far-apart angles next to each other.
  int k = (c.x & 3) + 4 * (c.y & 3);
  float angle = float((k * 7) & 15) * (6.2831853 / 16.0);
  vec3 r = vec3(cos(angle), sin(angle), 0.0);
  vec3 t = r - n * dot(r, n);
  if (dot(t, t) < 1e-6) t = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) - n * n.x : vec3(0.0, 1.0, 0.0) - n * n.y;
  t = normalize(t);
  mat3 tbn = mat3(t, cross(n, t), n);
  float open = 0.0;
  for (int i = 0; i < KERNEL_SIZE; ++i) {
    vec3 s = pos + tbn * uKernel[i] * uRadius;
    vec4 clip = uProjectionMatrix * vec4(s, 1.0);
    if (clip.w <= 0.0) {
      open += 1.0;
      continue;
    }
    vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * uSize;
    ivec2 q = ivec2(pixel);
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(uSize)))) {
      open += 1.0;  // off screen: nothing known covers it
      continue;
    }
    float sceneDepth = texelFetch(uDepth, q, 0).r;
    float sceneZ = sceneDepth >= 1.0 ? -1e30 : eyePosition(vec2(q) + 0.5, sceneDepth).z;
    // Covered when the surface there is nearer the eye than the point, by more than a little
    // (no self-occlusion on flat ground) and by less than the radius (a surface far in front
    // does not enclose this one).
    float nearer = sceneZ - s.z;
    float covered = nearer > 0.02 * uRadius ? 1.0 - smoothstep(0.5 * uRadius, uRadius, abs(pos.z - sceneZ)) : 0.0;
    open += 1.0 - covered;
  }
  fragColor = vec4(open / float(KERNEL_SIZE));
}
#endif
