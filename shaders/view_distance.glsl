// A window depth (0..1, as a depth buffer or gl_FragCoord.z holds it) as a distance along the
// view axis, for comparing depths drawn by different passes in eye units.
// `map`: P[2][2], P[3][2] of the projection, and 1 for perspective or 0 for orthographic
// (depthDistanceMap in renderer/core/camera.h).
#ifndef VIEW_DISTANCE_GLSL
#define VIEW_DISTANCE_GLSL

float viewDistance(float windowDepth, vec3 map) {
  float ndc = 2.0 * windowDepth - 1.0;
  return map.z > 0.5 ? map.y / (ndc + map.x) : (map.y - ndc) / map.x;
}

#endif
