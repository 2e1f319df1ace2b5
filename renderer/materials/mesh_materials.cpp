// Mesh materials as GL materials (see mesh_materials.h).
#include "renderer/materials/mesh_materials.h"

namespace npr {

Material glMaterial(const MeshMaterial& m, const LightingState& lighting, bool vertexColours) {
  Material g = m.fromLightingState ? lighting.front() : Material{};
  if (!m.fromLightingState) {
    g.ambient = glm::vec4(m.ambient, 1.0f);
    g.diffuse = glm::vec4(m.diffuse, 1.0f);
    g.specular = glm::vec4(m.specular, 1.0f);
    g.emission = glm::vec4(m.emission, 1.0f);
    g.shininess = m.shininess;
  }
  if (vertexColours) g.ambient = g.diffuse = glm::vec4(1.0f);
  return g;
}

std::vector<Material> glMaterials(const Mesh& mesh, const LightingState& lighting) {
  std::vector<Material> out;
  const bool colours = !mesh.colours.empty();
  for (const MeshMaterial& m : mesh.materials) out.push_back(glMaterial(m, lighting, colours));
  if (out.empty()) {  // vertex colours only: the lighting state's material, coloured
    MeshMaterial d;
    d.fromLightingState = true;
    out.push_back(glMaterial(d, lighting, colours));
  }
  return out;
}

std::vector<glm::vec3> faceColourScale(const Mesh& mesh, const Mesh& vertices) {
  const std::size_t nf = mesh.triangleCount();
  const bool colours = vertices.colours.size() == vertices.positions.size() && !vertices.colours.empty();
  const bool tints = mesh.faceTints.size() == nf && nf > 0;
  if (!colours && !tints) return {};
  std::vector<glm::vec3> scale(nf, glm::vec3(1.0f));
  for (std::size_t f = 0; f < nf; ++f) {
    if (colours) {
      const std::uint32_t* id = &mesh.indices[f * 3];
      scale[f] = (vertices.colours[id[0]] + vertices.colours[id[1]] + vertices.colours[id[2]]) / 3.0f;
    }
    if (tints) scale[f] *= mesh.faceTints[f];
  }
  return scale;
}

bool meshHasSpecular(const Mesh& mesh, const LightingState& lighting) {
  for (const MeshMaterial& m : mesh.materials)
    if (m.fromLightingState ? glm::any(glm::notEqual(glm::vec3(lighting.front().specular), glm::vec3(0.0f)))
                            : glm::any(glm::notEqual(m.specular, glm::vec3(0.0f))))
      return true;
  return mesh.materials.empty() && glm::any(glm::notEqual(glm::vec3(lighting.front().specular), glm::vec3(0.0f)));
}

LightingFeatures materialFeatures(const Mesh& mesh, const LightingState& lighting) {
  Material probe = lighting.front();
  probe.specular = meshHasSpecular(mesh, lighting) ? glm::vec4(1.0f) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  return lighting.withMaterial(probe).features();
}

}  // namespace npr
