// The depth cue: the paper blended over the surface by its distance through the scene (0 at
// the scene's front, 1 at its back), so tone and lines fade into the distance (seed 001:
// heavy in the foreground, lighter far away).
in float vDistance;
uniform vec2 uRange;     // scene front and back, eye distance
uniform vec2 uFade;      // the fade starts and ends at these fractions of the range
uniform float uStrength;
uniform vec3 uPaper;
layout(location = 0) out vec4 fragColor;
void main() {
  float t = (vDistance - uRange.x) / max(uRange.y - uRange.x, 1e-6);
  float fade = uStrength * smoothstep(uFade.x, max(uFade.y, uFade.x + 1e-4), t);
  if (!(fade > 1.0 / 512.0)) discard;
  fragColor = vec4(uPaper, fade);
}
