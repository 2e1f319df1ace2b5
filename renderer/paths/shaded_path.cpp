// Single-pass GPU-lit paths (see shaded_path.h).
#include "renderer/paths/shaded_path.h"

#include <algorithm>

#include "renderer/gl/pass_state.h"
#include "renderer/lighting/lighting_uniforms.h"
#include "renderer/lighting/mesh_materials.h"

namespace npr {

Status ShadedPath::draw(FrameContext& f) {
  gl::MeshProgram variant;
  switch (kind_) {
    case Kind::Vertex: variant.shading = gl::MeshShading::Vertex; break;
    case Kind::Pixel: variant.shading = gl::MeshShading::Pixel; break;
    case Kind::Smooth: variant.shading = gl::MeshShading::Smooth; break;
    case Kind::LitTextured: variant.shading = gl::MeshShading::LitTextured; break;
    case Kind::Reference:
      variant.shading = f.settings.referenceGouraud ? gl::MeshShading::Gouraud : gl::MeshShading::Phong;
      break;
  }
  const bool usesPalette = kind_ != Kind::Reference;
  variant.output = f.output;
  const bool materials = f.drawMaterials();
  variant.materials = materials;
  variant.materialMaps = materials && f.materials.hasMaps();
  variant.vertexColours = materials && !f.mesh.colours.empty();
  variant.lighting = materials ? materialFeatures(f.mesh, f.lighting) : f.lighting.features();
  if (f.shadows) variant.shadowLayers = f.shadows->layers();
  variant.occlusion = kind_ != Kind::LitTextured && f.settings.occlusion && f.gpuMesh.hasOcclusion();
  if (usesPalette) {
    variant.palette = f.paletteVariant();
    variant.stroke = f.strokeSource();
  }
  Result<gl::ShaderProgram*> prog = f.program(variant);
  if (!prog) return Error{prog.error()};
  gl::ShaderProgram& p = **prog;
  gl::apply(gl::pass::kMesh);
  p.use();
  setMeshTransform(p, f.camera);
  if (materials) {
    uploadMaterialLightingUniforms(p, f.lighting, glm::mat4(1.0f));
    f.materials.bind(p);
  } else {
    uploadLightingUniforms(p, prepareLighting<float>(f.lighting));
  }
  if (usesPalette) f.bindPalette(p);
  if (f.shadows) f.shadows->bind(p, f.camera.view);
  if (variant.occlusion) p.set("uOcclusionStrength", std::clamp(f.settings.occlusionStrength, 0.0f, 1.0f));
  f.gpuMesh.drawAll();
  ++f.stats.drawCalls;
  return okStatus();
}

}  // namespace npr
