// libFuzzer harness: the OBJ reader on arbitrary bytes, whole and split into its groups
// (--split-objects), never crashes, hangs or leaks, and what it accepts is meshes the renderer
// can draw (fuzz_mesh.h), the groups holding no more triangles than the whole.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_mesh.h"
#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/obj_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  npr::Result<npr::Mesh> m = npr::parseObj("fuzz.obj", bytes);
  const std::size_t whole = m ? m->triangleCount() : 0;
  npr::fuzz::checkMesh(m);
  npr::Result<std::vector<npr::ObjObject>> parts = npr::parseObjObjects("fuzz.obj", bytes);
  if (!parts) {
    if (parts.error().empty()) __builtin_trap();
    return 0;
  }
  std::size_t sum = 0;
  for (npr::ObjObject& o : *parts) {
    sum += o.mesh.triangleCount();
    npr::Result<npr::Mesh> one = std::move(o.mesh);
    npr::fuzz::checkMesh(one);
  }
  if (sum > whole) __builtin_trap();
  return 0;
}
