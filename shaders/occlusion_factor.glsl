// How much of the ambient and diffuse light an occlusion value (1: open) leaves at a strength
// (0: none of it, 1: all): the one formula every stage uses. lighting/occlusion_factor.h is the
// same in C++, for the per-triangle paths on the CPU and the benchmark's reference.
#ifndef OCCLUSION_FACTOR_GLSL
#define OCCLUSION_FACTOR_GLSL
float occlusionFactor(float occlusion, float strength) { return mix(1.0, clamp(occlusion, 0.0, 1.0), strength); }
#endif
