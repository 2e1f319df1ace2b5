// libFuzzer harness: the .mtl reader on arbitrary bytes never crashes, hangs or leaks, and
// every material it yields is within OpenGL's ranges (colours in [0,1], shininess in
// [0,128], opacity in [0,1]).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/mesh/mtl_parser.h"
#include "renderer/mesh/polygon_soup.h"

namespace {
bool unit(const glm::vec3& c) {
  for (int k = 0; k < 3; ++k)
    if (!(c[k] >= 0.0f && c[k] <= 1.0f)) return false;
  return true;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<npr::MtlMaterial> out;
  std::vector<std::string> messages;
  npr::Warnings warnings(messages);
  npr::parseMtl("fuzz-dir/fuzz.mtl", text, out, warnings);
  warnings.finish();
  for (const npr::MtlMaterial& m : out) {
    const npr::MeshMaterial& g = m.material;
    if (!unit(g.ambient) || !unit(g.diffuse) || !unit(g.specular) || !unit(g.emission)) __builtin_trap();
    if (!(g.shininess >= 0.0f && g.shininess <= 128.0f) || !(g.opacity >= 0.0f && g.opacity <= 1.0f)) __builtin_trap();
  }
  if (messages.size() > 51) __builtin_trap();  // the warning budget holds
  return 0;
}
