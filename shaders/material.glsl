// The mesh's material table (MATERIALS): one RGBA32UI texel per material, its colours in
// 8 bits a channel: x = ambient | (map layer + 1) << 24, y = diffuse | shininess high byte,
// z = specular | shininess low byte, w = emission | coverage (coverage.glsl; shininess in 1/512ths, see
// renderer/mesh/gpu_materials.h). The per-pixel paths fetch per fragment: one fetch, where
// four float texels cost llvmpipe about 5% of the pixel path's frame, and flat varyings 15%.
#ifndef MATERIAL_GLSL
#define MATERIAL_GLSL

#ifdef MATERIAL_MAPS
uniform sampler2DArray uMaterialMaps;  // diffuse maps, mipmapped, repeating (one layer per map)
#endif

struct SurfaceMaterial {
  vec3 ambient, diffuse, specular, emission;
  float shininess, map;
  float coverage;  // the row's top byte: how alpha leaves fragments out (coverage.glsl)
};

#ifdef MATERIAL_UNIFORM
// One material per draw (the GPU-lit paths draw the mesh material by material): the table's
// row as uniforms, unpacked on the CPU to the same values; nothing fetched per pixel.
uniform vec3 uMaterialColours[4];  // ambient, diffuse, specular, emission
uniform float uMaterialShininess;
uniform float uMaterialMap;  // layer of the diffuse maps, -1: none
uniform float uMaterialCoverage;
SurfaceMaterial fetchMaterial(uint index) {
  return SurfaceMaterial(uMaterialColours[0], uMaterialColours[1], uMaterialColours[2], uMaterialColours[3], uMaterialShininess,
                         uMaterialMap, uMaterialCoverage);
}
#else
uniform usamplerBuffer uMaterialTable;

vec3 unpackColour(uint v) { return vec3(float(v & 255u), float((v >> 8) & 255u), float((v >> 16) & 255u)) / 255.0; }

SurfaceMaterial fetchMaterial(uint index) {
  uvec4 t = texelFetch(uMaterialTable, int(index));
  float shininess = float(((t.y >> 24) << 8) | (t.z >> 24)) / 512.0;
  return SurfaceMaterial(unpackColour(t.x), unpackColour(t.y), unpackColour(t.z), unpackColour(t.w), shininess,
                         float(t.x >> 24) - 1.0, float(t.w >> 24));
}
#endif

#endif
