// Vertex stage shared by every mesh pass. gl_Position is computed by the same expression in
// every variant and declared invariant, so the stencil path's passes produce equal depths.
// PER_VERTEX_LIGHTING (the `vertex` path and Gouraud reference) lights here. MATERIALS adds
// the mesh's own appearance: a colour (white where the mesh has none), texture coordinates
// and a material index per vertex (vertices are split where these differ); ALPHA_COVERAGE passes
// the material and coordinates on in every pass (coverage.glsl). ORIENT_FIELD passes
// the hatching direction field on (orientation.glsl); OCCLUSION the baked ambient occlusion.
// CONTROL_SHADOW / CONTROL_OCCLUSION with per-vertex lighting pass the control-image palette's
// weight on (mesh.frag).

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModelView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;
uniform mat4 uModelViewProjection;  // uProjection * uModelView

invariant gl_Position;

out vec3 vPosition;  // eye space
out vec3 vNormal;    // eye space, not normalised

#if defined(MATERIALS) || defined(ALPHA_COVERAGE)
#include "material.glsl"
layout(location = 2) in vec3 aColour;
layout(location = 3) in vec2 aTexcoord;
layout(location = 4) in uint aMaterial;
layout(location = 5) in vec3 aMapAverage;  // the diffuse map around this vertex (per-vertex paths)
#endif
#if defined(MATERIALS) && !defined(PER_VERTEX_LIGHTING) && defined(VERTEX_COLOURS)
out vec3 vColour;
#endif
// The material and map coordinates reach the fragment stage where it lights with them, or
// where it decides coverage (ALPHA_COVERAGE: see-through materials, in every pass).
#if (defined(MATERIALS) && !defined(PER_VERTEX_LIGHTING)) || defined(ALPHA_COVERAGE)
#define MATERIAL_VARYINGS
#ifdef MATERIAL_MAPS
out vec2 vTexcoord;
#endif
#ifndef MATERIAL_UNIFORM
flat out uint vMaterial;
#endif
#endif

#ifdef ORIENT_FIELD
layout(location = 6) in vec3 aDirection;  // the hatching direction field (zero: none)
#endif
#if defined(ORIENT_FIELD) || defined(ORIENT_LIGHT)
#include "orientation.glsl"
out vec2 vStrokeDirection;  // unit, on screen; zero: none
#endif

#include "pattern_vertex.glsl"

#ifdef PATTERN_REST
// A deforming mesh's rest pose (GpuMesh): where the object-space pattern is read, so it stays
// on the surface as the surface bends.
layout(location = 8) in vec3 aRestPosition;
layout(location = 9) in vec3 aRestNormal;
out vec3 vRestPosition;
out vec3 vRestNormal;
#endif

#ifdef GROUND_SHADOW_MAP
out vec2 vGroundXZ;  // where the ground's shadow texture is read (lighting.glsl)
#endif

#ifdef OCCLUSION
layout(location = 7) in float aOcclusion;  // baked: 1 open, 0 enclosed
uniform float uOcclusionStrength;
#include "occlusion_factor.glsl"
out float vOcclusion;  // what ambient and diffuse are scaled by
#endif

#ifdef PER_VERTEX_LIGHTING
#include "lighting.glsl"
out vec3 vColorFront;
out vec3 vColorBack;
#if defined(CONTROL_SHADOW) || defined(CONTROL_OCCLUSION)
out float vControl;
#endif
#endif

void main() {
  vec4 eye = uModelView * vec4(aPosition, 1.0);
  gl_Position = uProjection * eye;
  setPatternCoordinate(gl_Position);
  vPosition = eye.xyz;
  vNormal = uNormalMatrix * aNormal;
#ifdef PATTERN_REST
  vRestPosition = aRestPosition;
  vRestNormal = aRestNormal;
#endif
#ifdef GROUND_SHADOW_MAP
  vGroundXZ = aPosition.xz;
#endif
#if defined(ORIENT_FIELD)
  // A tangent turns with the modelview, not the normal matrix; w = 0 takes it to clip space
  // as a direction, in one product with the projection.
  vStrokeDirection = screenDirectionClip(gl_Position, uModelViewProjection * vec4(aDirection, 0.0));
#elif defined(ORIENT_LIGHT)
  vStrokeDirection = screenDirectionClip(gl_Position, uProjection * vec4(lightAcrossSurface(eye.xyz, vNormal), 0.0));
#endif
#if defined(MATERIALS) && !defined(PER_VERTEX_LIGHTING) && defined(VERTEX_COLOURS)
  vColour = aColour;
#endif
#ifdef MATERIAL_VARYINGS
#ifdef MATERIAL_MAPS
  vTexcoord = aTexcoord;
#endif
#ifndef MATERIAL_UNIFORM
  vMaterial = aMaterial;
#endif
#endif
#ifdef OCCLUSION
  vOcclusion = occlusionFactor(aOcclusion, uOcclusionStrength);
  float occlusion = vOcclusion;
#else
  float occlusion = 1.0;
#endif
#if defined(PER_VERTEX_LIGHTING) && defined(MATERIALS)
  SurfaceMaterial mat = fetchMaterial(aMaterial);
  vColorFront = shadeScaled(mat, eye.xyz, vNormal, false, aColour * aMapAverage * occlusion);
#ifdef TWO_SIDED
  vColorBack = shadeScaled(mat, eye.xyz, vNormal, true, aColour * aMapAverage * occlusion);
#else
  vColorBack = vColorFront;
#endif
#elif defined(PER_VERTEX_LIGHTING)
  vColorFront = shadeScaled(eye.xyz, vNormal, false, vec3(occlusion));
#ifdef TWO_SIDED
  vColorBack = shadeScaled(eye.xyz, vNormal, true, vec3(occlusion));
#else
  vColorBack = vColorFront;
#endif
#endif
#if defined(PER_VERTEX_LIGHTING) && defined(CONTROL_OCCLUSION)
  vControl = 1.0 - occlusion;
#elif defined(PER_VERTEX_LIGHTING) && defined(CONTROL_SHADOW)
  vControl = shadowShareAt(eye.xyz, vNormal, false);
#endif
}
