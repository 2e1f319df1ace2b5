// A mesh restricted to some of its faces, for drawing parts of a model with different
// palettes (per-material palettes): every vertex array and material is kept (indices stay
// valid), the per-face arrays keep the chosen faces in order. The texture maps are left out:
// a part lights with the whole's face tints (copied per face) and draws through its maps.
#pragma once

#include <vector>

#include "renderer/mesh/mesh.h"

namespace npr {

// `keep` has one flag per triangle of `mesh`.
Mesh meshSubset(const Mesh& mesh, const std::vector<char>& keep);

}  // namespace npr
