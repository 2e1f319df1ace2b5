// The mesh's material table (MATERIALS): one row of 4 RGBA32F texels per material,
// (ambient, map layer or -1), (diffuse, 0), (specular, shininess), (emission, 0); see
// renderer/mesh/gpu_materials.h. The per-pixel paths fetch per fragment: passing the rows as
// flat varyings instead made llvmpipe's frame about 15% slower on the 871K-triangle mesh.
#ifndef MATERIAL_GLSL
#define MATERIAL_GLSL

uniform samplerBuffer uMaterialTable;

struct SurfaceMaterial {
  vec3 ambient, diffuse, specular, emission;
  float shininess, map;
};
SurfaceMaterial materialFromRows(vec4 a, vec4 d, vec4 s, vec4 e) {
  return SurfaceMaterial(a.rgb, d.rgb, s.rgb, e.rgb, s.a, a.a);
}

vec4 materialRow(uint index, int k) { return texelFetch(uMaterialTable, int(index) * 4 + k); }

SurfaceMaterial fetchMaterial(uint index) {
  vec4 a = materialRow(index, 0), d = materialRow(index, 1), e = materialRow(index, 3);
#ifdef HAS_SPECULAR
  vec4 s = materialRow(index, 2);
#else
  vec4 s = vec4(0.0);  // not read: the specular term is compiled out
#endif
  return materialFromRows(a, d, s, e);
}

#endif
