// Ambient occlusion bake (renderer/shadows/occlusion_bake.h), one direction per draw: each
// vertex, drawn as a point onto its own texel of an accumulation target, adds whether it sees
// the sky in that direction (the direction's depth map), weighted by the cosine to its normal,
// and the cosine alone; their ratio over all directions is the vertex's openness.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uDirectionViewProjection;  // model -> the direction's orthographic clip space
uniform vec3 uDirection;                // model space, toward the sky
uniform sampler2DShadow uDepth;
uniform float uOffset;                  // off the surface by about two depth texels
uniform ivec2 uTargetSize;

out vec2 vSample;

void main() {
  vec3 n = normalize(aNormal);
  float c = dot(n, uDirection);
  float seen = 0.0;
  if (c > 0.0) {
    vec4 clip = uDirectionViewProjection * vec4(aPosition + n * uOffset, 1.0);
    vec3 uvz = clip.xyz * 0.5 + 0.5;
    seen = any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0))) ? 1.0 : texture(uDepth, uvz);
  }
  vSample = vec2(max(c, 0.0) * seen, max(c, 0.0));
  ivec2 texel = ivec2(gl_VertexID % uTargetSize.x, gl_VertexID / uTargetSize.x);
  gl_Position = vec4((vec2(texel) + 0.5) / vec2(uTargetSize) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
