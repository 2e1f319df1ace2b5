// GPU-lit mesh programs (see lit_mesh_program.h).
#include "renderer/paths/lit_mesh_program.h"


#include "renderer/lighting/lighting_uniforms.h"
#include "renderer/materials/mesh_materials.h"

namespace npr {

gl::MeshProgram litMeshProgram(const FrameContext& f, gl::MeshShading shading, const GpuPalette* palette) {
  gl::MeshProgram variant;
  variant.shading = shading;
  variant.output = f.output;
  const bool materials = f.drawMaterials();
  variant.materials = materials;
  variant.materialMaps = materials && f.materials.hasMaps();
  variant.vertexColours = materials && !f.mesh.colours.empty();
  variant.lighting = materials ? materialFeatures(f.mesh, f.lighting) : f.lighting.features();
  if (palette) {
    variant.palette = f.paletteVariant(palette);
    variant.stroke = f.strokeSource(palette);
  }
  for (std::size_t i = 0; i < f.inputCount; ++i) f.inputs[i]->addTo(variant, f);
  return variant;
}

void bindLitMesh(const FrameContext& f, gl::ShaderProgram& p, const gl::MeshProgram& variant, const GpuPalette* palette) {
  p.use();
  setMeshTransform(p, f.camera);
  if (variant.materials) {
    uploadMaterialLightingUniforms(p, f.lighting, glm::mat4(1.0f));
    f.materials.bind(p);
  } else {
    uploadLightingUniforms(p, prepareLighting<float>(f.lighting));
  }
  if (palette) f.bindPalette(p, palette);
  for (std::size_t i = 0; i < f.inputCount; ++i) f.inputs[i]->bind(p, variant, f);
}

}  // namespace npr
