// The supersampled frame box-filtered down (frame/supersample.h): each output pixel the mean
// of the FACTOR x FACTOR source pixels it covers, alpha included. A box, not a wider filter:
// a palette texel covering whole blocks comes out exactly as drawn, with no shimmer.
uniform sampler2D uSource;
uniform int uFactor;
uniform vec2 uOrigin;  // the viewport's corner in the framebuffer drawn into
out vec4 fragColor;
void main() {
  ivec2 base = ivec2(gl_FragCoord.xy - uOrigin) * uFactor;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < uFactor; ++j)
    for (int i = 0; i < uFactor; ++i) sum += texelFetch(uSource, base + ivec2(i, j), 0);
  fragColor = sum / float(uFactor * uFactor);
}
