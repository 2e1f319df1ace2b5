// Hardware outlines: the silhouette colour. The charcoal rim (OUTLINE_RIM): the palette entry
// its tone matches, in the palette's own screen-space pattern, so it reads as the same
// charcoal as the faces beside it.
#ifdef OUTLINE_RIM
#include "palette.glsl"
flat in float gTone;
#else
uniform vec3 uColour;
#endif
out vec4 fragColor;

void main() {
#ifdef OUTLINE_RIM
  fragColor = vec4(paletteColour(matchEntry(vec3(gTone))), 1.0);
#else
  fragColor = vec4(uColour, 1.0);
#endif
}
