// libFuzzer harness: an OM file (OpenMesh's binary format) never takes the process down.
// OpenMesh's reader runs in a child process (om_reader.cpp); whatever the child does, the
// parent must come back with a mesh the renderer can draw or a message.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz_mesh.h"
#include "renderer/mesh/mesh_formats.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/npr-fuzz-om-" + std::to_string(::getpid()) + ".om";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  npr::Result<npr::Mesh> m = npr::loadOm(path, 3);  // well under libFuzzer's 10 s timeout, ASan's slower fork and exit included
  npr::fuzz::checkMesh(m);
  return 0;
}
