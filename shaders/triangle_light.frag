// Per-triangle lighting on the GPU: the lit colour matched to a palette entry, as an integer.
#include "palette.glsl"
flat in vec3 vLit;
out uvec4 fragEntry;
void main() { fragEntry = uvec4(uint(matchEntry(vLit)), 0u, 0u, 0u); }
