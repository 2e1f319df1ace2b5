// libFuzzer harness: the glTF reader (tinygltf's JSON and GLB parsing, then our checks of every
// accessor, buffer view, node and material) on arbitrary bytes, JSON and GLB alike, never
// crashes, hangs or leaks, and what it accepts is a mesh the renderer can draw (fuzz_mesh.h).
// External files are looked up beside a folder that does not exist, so none is ever read.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_mesh.h"
#include "renderer/mesh/mesh_formats.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  npr::Result<npr::Mesh> m = npr::parseGltf("/nonexistent-npr-fuzz/fuzz.gltf", bytes);
  npr::fuzz::checkMesh(m);
  return 0;
}
