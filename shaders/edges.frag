// Image-space edges: Sobel on linear depth (relative to the centre's depth) and on normals,
// combined and thresholded; drawn as ink over the frame. Catches edges the object-space lines
// miss (intersections, contours between non-adjacent surfaces).
uniform sampler2D uNormals;  // eye-space normals; alpha 0 where no surface
uniform sampler2D uDepth;
uniform ivec2 uOrigin;       // the viewport's corner in the framebuffer
uniform vec2 uProjection;    // P[2][2], P[3][2]: to linearise depth
uniform float uThreshold;
uniform vec3 uInk;
out vec4 fragColor;

float linearDepth(ivec2 p) {
  float z = texelFetch(uDepth, p, 0).r * 2.0 - 1.0;
  return uProjection.y / (z + uProjection.x);  // negative eye-space z, up to sign
}

void main() {
  ivec2 c = ivec2(gl_FragCoord.xy) - uOrigin;
  ivec2 size = textureSize(uDepth, 0);
  float d[9];
  vec3 n[9];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      ivec2 p = clamp(c + ivec2(i - 1, j - 1), ivec2(0), size - 1);
      d[j * 3 + i] = abs(linearDepth(p));
      vec4 t = texelFetch(uNormals, p, 0);
      n[j * 3 + i] = t.a > 0.0 ? normalize(t.xyz + vec3(1e-9)) : vec3(0.0);
    }
  float gx = (d[2] + 2.0 * d[5] + d[8]) - (d[0] + 2.0 * d[3] + d[6]);
  float gy = (d[6] + 2.0 * d[7] + d[8]) - (d[0] + 2.0 * d[1] + d[2]);
  float depthEdge = length(vec2(gx, gy)) / max(min(d[4], 1e30), 1e-6);
  vec3 nx = (n[2] + 2.0 * n[5] + n[8]) - (n[0] + 2.0 * n[3] + n[6]);
  vec3 ny = (n[6] + 2.0 * n[7] + n[8]) - (n[0] + 2.0 * n[1] + n[2]);
  float normalEdge = 0.25 * sqrt(dot(nx, nx) + dot(ny, ny));
  float e = max(depthEdge * 4.0, normalEdge);
  float alpha = smoothstep(uThreshold, uThreshold * 1.5, e);
  if (alpha <= 0.0) discard;
  fragColor = vec4(uInk, alpha);
}
