// A deforming mesh's pose on the GPU (renderer/animation/gpu_deformation.h): the same morphing
// and linear blend skinning as the CPU's deformMesh (animation/deformation.h), written into the
// buffers every pass draws from, once per pose, so the mesh passes, shadows, outlines and the
// stencil path's masks all see the pose without a variant of their own. Vec3 streams are tight
// (12 bytes a vertex, as the vertex arrays read them), so they are float arrays here: std430
// would pad a vec3 array to 16. VECTORS carries direction vectors (the hatching field's
// tangents) by the skin alone, unnormalised, as the CPU does.
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer RestPositions { float restPositions[]; };
layout(std430, binding = 2) writeonly buffer Positions { float positions[]; };
#ifndef VECTORS
layout(std430, binding = 1) readonly buffer RestNormals { float restNormals[]; };
layout(std430, binding = 3) writeonly buffer Normals { float normals[]; };
#endif
#ifdef SKIN
// Per vertex: two words of four 16-bit joint indices, then four weights' bits.
layout(std430, binding = 4) readonly buffer Skin { uint skin[]; };
layout(std430, binding = 5) readonly buffer Joints { mat4 joints[]; };
uniform uint uJointCount;
#endif
#ifdef MORPH
// Per target, per vertex: the position delta, then the normal delta.
layout(std430, binding = 6) readonly buffer Targets { float targets[]; };
uniform int uActiveTargets;
uniform int uTarget[MAX_ACTIVE_TARGETS];
uniform float uTargetWeight[MAX_ACTIVE_TARGETS];
#endif
uniform uint uVertexCount;

vec3 read3(uint i, bool normal) {
#ifndef VECTORS
  if (normal) return vec3(restNormals[3u * i], restNormals[3u * i + 1u], restNormals[3u * i + 2u]);
#endif
  return vec3(restPositions[3u * i], restPositions[3u * i + 1u], restPositions[3u * i + 2u]);
}

#ifdef SKIN
mat4 joint(uint k) { return joints[min(k, uJointCount - 1u)]; }
#endif

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uVertexCount) return;
  vec3 p = read3(i, false);
#ifndef VECTORS
  vec3 n = read3(i, true);
#endif
#ifdef MORPH
  for (int t = 0; t < uActiveTargets; ++t) {
    uint at = (uint(uTarget[t]) * uVertexCount + i) * 6u;
    float w = uTargetWeight[t];
    p += w * vec3(targets[at], targets[at + 1u], targets[at + 2u]);
    n += w * vec3(targets[at + 3u], targets[at + 4u], targets[at + 5u]);
  }
#endif
#ifdef SKIN
  uint s = 6u * i;
  vec4 w = vec4(uintBitsToFloat(skin[s + 2u]), uintBitsToFloat(skin[s + 3u]), uintBitsToFloat(skin[s + 4u]), uintBitsToFloat(skin[s + 5u]));
  if (w.x + w.y + w.z + w.w > 0.0) {
    uint j01 = skin[s], j23 = skin[s + 1u];
    mat4 m = w.x * joint(j01 & 0xFFFFu) + w.y * joint(j01 >> 16) + w.z * joint(j23 & 0xFFFFu) + w.w * joint(j23 >> 16);
#ifdef VECTORS
    p = mat3(m) * p;
#else
    p = vec3(m * vec4(p, 1.0));
    n = mat3(m) * n;
#endif
  }
#endif
  positions[3u * i] = p.x;
  positions[3u * i + 1u] = p.y;
  positions[3u * i + 2u] = p.z;
#ifndef VECTORS
  float len = length(n);
  n = len > 0.0 && !isinf(len) && !isnan(len) ? n / len : vec3(0.0, 0.0, 1.0);
  normals[3u * i] = n.x;
  normals[3u * i + 1u] = n.y;
  normals[3u * i + 2u] = n.z;
#endif
}
