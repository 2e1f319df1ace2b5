// Test helpers (see test_util.h).
#include "support/test_util.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <unistd.h>

namespace npr::test {

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("npr-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string TempDir::write(const std::string& name, const std::string& content) const {
  const auto p = path_ / name;
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << content;
  return p.string();
}

Mesh sphereInMaterial(int level, const std::string& name, const glm::vec3& colour) {
  Mesh m = icosphere(level);
  MeshMaterial material;
  material.name = name;
  material.ambient = material.diffuse = colour;
  m.materials = {material};
  m.faceMaterials.assign(m.triangleCount(), 0);
  return m;
}

Mesh square(int n) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.emplace_back(2.0f * float(i) / float(n) - 1.0f, 2.0f * float(j) / float(n) - 1.0f, 0.0f);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + std::uint32_t(n) + 2, d = a + std::uint32_t(n) + 1;
      for (std::uint32_t v : {a, b, c, a, c, d}) m.indices.push_back(v);
    }
  finalizeMesh(m);
  return m;
}

void writeObj(const Mesh& m, const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "w");
  for (const auto& p : m.positions) std::fprintf(f, "v %.7f %.7f %.7f\n", p.x, p.y, p.z);
  for (size_t i = 0; i < m.indices.size(); i += 3) std::fprintf(f, "f %u %u %u\n", m.indices[i] + 1, m.indices[i + 1] + 1, m.indices[i + 2] + 1);
  std::fclose(f);
}

std::string outputPath(const std::string& name) {
  std::error_code ec;
  std::filesystem::create_directories(NPR_TEST_OUTPUT_DIR, ec);
  return (std::filesystem::path(NPR_TEST_OUTPUT_DIR) / name).string();
}

}  // namespace npr::test
