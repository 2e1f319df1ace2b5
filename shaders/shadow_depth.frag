// Depth only: the fixed-function depth write is the whole output. A see-through caster
// (ALPHA_COVERAGE) leaves out what its material leaves out for the eye, so light passes there.
#ifdef ALPHA_COVERAGE
#include "coverage.glsl"
in vec2 vTexcoord;
flat in uint vMaterial;
#endif
void main() {
#ifdef ALPHA_COVERAGE
  if (!covered(vMaterial, vTexcoord)) discard;
#endif
}
