// Which fragments of a see-through surface are drawn (ALPHA_COVERAGE: glTF's MASK and BLEND;
// renderer/mesh/gpu_materials.h says why a blend is screen-door transparency). Fragment stage
// only. The material's coverage code is its table row's top byte (gpu_materials.cpp's
// coverageCode): 0 opaque; 1..126 a mask's cutoff on the map's alpha, (code - 1) / 125;
// 127 a mask never reached; 128..255 a blend's opacity, (code - 128) / 127.
#ifndef COVERAGE_GLSL
#define COVERAGE_GLSL

#include "material.glsl"

// The 4x4 ordered-dither (Bayer) thresholds: every level of alpha covers its share of each
// block, spread as evenly as 16 pixels allow, and a still view draws the same pixels each frame.
const float kCoverageDither[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);

// Whether the fragment of `material` at map coordinates `uv` is drawn.
bool covered(uint material, vec2 uv) {
  SurfaceMaterial m = fetchMaterial(material);
#ifdef MATERIAL_MAPS
  float mapAlpha = m.map >= 0.0 ? texture(uMaterialMaps, vec3(uv, m.map)).a : 1.0;
#else
  float mapAlpha = 1.0;
#endif
  float code = m.coverage;
  if (code < 0.5) return true;
  if (code < 127.5) return code < 126.5 && mapAlpha >= (code - 1.0) / 125.0;
  ivec2 p = ivec2(gl_FragCoord.xy) & 3;
  return (code - 128.0) / 127.0 * mapAlpha > (kCoverageDither[p.y * 4 + p.x] + 0.5) / 16.0;
}

#endif
