// A mesh's own materials as OpenGL materials (--materials on): what each face is lit with,
// on the CPU (per-triangle paths) and on the GPU (the material table, gpu_materials.h).
#pragma once

#include <vector>

#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh.h"

namespace npr {

// One GL material per mesh material. The default material ("(default)", and materials no
// library defines) is the lighting state's front material. With vertex colours the ambient
// and diffuse colours are white here: each face's colour scales them (GL_COLOR_MATERIAL's
// AMBIENT_AND_DIFFUSE, see faceColourScale).
std::vector<Material> glMaterials(const Mesh& mesh, const LightingState& lighting);
Material glMaterial(const MeshMaterial& m, const LightingState& lighting, bool vertexColours);

// Per triangle, what scales its material's ambient and diffuse colours: the mean of its
// vertex colours times its texture map's average over it. Empty when neither exists.
// `vertices`: the mesh whose vertex colours `mesh`'s indices point into (`mesh` itself, or the
// whole it is part of: mesh_subset.h).
std::vector<glm::vec3> faceColourScale(const Mesh& mesh, const Mesh& vertices);

// Whether any material (or vertex colour) can give a specular term.
bool meshHasSpecular(const Mesh& mesh, const LightingState& lighting);
// The lighting features a program needs to draw the mesh's materials (specular from them).
LightingFeatures materialFeatures(const Mesh& mesh, const LightingState& lighting);

}  // namespace npr
