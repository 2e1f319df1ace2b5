// libFuzzer harness: the PLY reader on arbitrary bytes never crashes, hangs or leaks, and
// what it accepts is a mesh the renderer can draw (fuzz_mesh.h).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_mesh.h"
#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/obj_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  npr::Result<npr::Mesh> m = npr::parsePly("fuzz.ply", bytes);
  npr::fuzz::checkMesh(m);
  return 0;
}
