// The vignette: the paper blended over the frame toward its edges, so the drawing fades out
// into the page as a book illustration's does. r is 0 at the viewport's centre and 1 at its
// corners; the fade starts at uRadius and is whole uSoftness later.
uniform vec4 uViewport;  // x, y, width, height in framebuffer pixels
uniform float uRadius;
uniform float uSoftness;
uniform float uStrength;
uniform vec3 uPaper;
layout(location = 0) out vec4 fragColor;
void main() {
  vec2 p = (gl_FragCoord.xy - uViewport.xy) / uViewport.zw * 2.0 - 1.0;
  float r = length(p) * 0.70710678;
  float fade = uStrength * smoothstep(uRadius, uRadius + max(uSoftness, 1e-4), r);
  if (!(fade > 1.0 / 512.0)) discard;
  fragColor = vec4(uPaper, fade);
}
