// The post-process anti-aliasing filter (aa fxaa; frame/supersample.h), in the manner of FXAA:
// the frame drawn at its own size is read back per pixel; where the luma of a pixel and its
// neighbours spans enough contrast, the pixel is blended with its neighbour across the edge by
// how far it sits from the edge's middle (the edge's ends found by a short walk along it) or,
// for a pixel-sized feature, by how far it stands out of its 3x3 average. It needs no
// second draw of the scene, but it cannot tell a tone band's step from a palette texel's:
// hatching's strokes are softened too.
uniform sampler2D uSource;
uniform vec2 uOrigin;  // the viewport's corner in the framebuffer drawn into
uniform ivec2 uSize;   // the frame's size in the source
out vec4 fragColor;

const int kSteps = 8;  // how far along an edge its ends are looked for, pixels each way

vec4 at(ivec2 p) { return texelFetch(uSource, clamp(p, ivec2(0), uSize - 1), 0); }
float luma(vec4 c) { return dot(c.rgb, vec3(0.299, 0.587, 0.114)); }
float lumaAt(ivec2 p) { return luma(at(p)); }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy - uOrigin);
  vec4 c = at(p);
  float m = luma(c);
  float n = lumaAt(p + ivec2(0, 1)), s = lumaAt(p - ivec2(0, 1)), e = lumaAt(p + ivec2(1, 0)), w = lumaAt(p - ivec2(1, 0));
  float lo = min(m, min(min(n, s), min(e, w))), hi = max(m, max(max(n, s), max(e, w)));
  float range = hi - lo;
  if (range < max(0.0625, 0.125 * hi)) {  // flat, or contrast the eye does not see stepped
    fragColor = c;
    return;
  }
  float ne = lumaAt(p + ivec2(1, 1)), nw = lumaAt(p + ivec2(-1, 1)), se = lumaAt(p + ivec2(1, -1)), sw = lumaAt(p + ivec2(-1, -1));
  // An edge running along x changes most across y.
  float alongX = 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e) + abs(nw + sw - 2.0 * w);
  float alongY = 2.0 * abs(e + w - 2.0 * m) + abs(ne + nw - 2.0 * n) + abs(se + sw - 2.0 * s);
  bool horizontal = alongX >= alongY;
  ivec2 along = horizontal ? ivec2(1, 0) : ivec2(0, 1);
  float before = horizontal ? s : w, after = horizontal ? n : e;
  bool towardsAfter = abs(after - m) >= abs(before - m);
  ivec2 across = (towardsAfter ? 1 : -1) * (horizontal ? ivec2(0, 1) : ivec2(1, 0));
  float other = towardsAfter ? after : before;
  float middle = 0.5 * (m + other);               // the edge's luma, between the two sides
  float threshold = 0.25 * abs(other - m);
  // Walk both ways along the edge, reading the mean of the two sides, until it leaves the middle.
  int toStart = kSteps, toEnd = kSteps;
  float startLuma = middle, endLuma = middle;
  for (int i = 1; i <= kSteps; ++i) {
    float l = 0.5 * (lumaAt(p - along * i) + lumaAt(p - along * i + across));
    if (abs(l - middle) >= threshold) {
      toStart = i;
      startLuma = l;
      break;
    }
  }
  for (int i = 1; i <= kSteps; ++i) {
    float l = 0.5 * (lumaAt(p + along * i) + lumaAt(p + along * i + across));
    if (abs(l - middle) >= threshold) {
      toEnd = i;
      endLuma = l;
      break;
    }
  }
  // The pixel is blended where the edge's nearer end steps the way this pixel does.
  bool startNearer = toStart < toEnd;
  float endStep = (startNearer ? startLuma : endLuma) - middle;
  float edgeBlend = (endStep < 0.0) != (m - middle < 0.0) ? 0.5 - float(min(toStart, toEnd)) / float(toStart + toEnd) : 0.0;
  // A feature about a pixel wide: blended by how far it stands out of its neighbourhood.
  float mean = (2.0 * (n + s + e + w) + ne + nw + se + sw) / 12.0;
  float standsOut = clamp(abs(mean - m) / range, 0.0, 1.0);
  standsOut = smoothstep(0.0, 1.0, standsOut);
  float subpixel = standsOut * standsOut * 0.75;
  fragColor = mix(c, at(p + across), max(edgeBlend, subpixel));
}
