// Meshes built in code (see mesh_generators.h).
#include "renderer/mesh/mesh_generators.h"

#include <array>
#include <cmath>
#include <map>

#include "renderer/mesh/mesh_builder.h"

namespace npr {

Mesh icosphere(int level) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<glm::vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                       {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                       {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (auto& p : v) p = glm::normalize(p);
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(glm::normalize(v[size_t(a)] + v[size_t(b)]));
      return mid[key] = int(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> nf;
    nf.reserve(f.size() * 4);
    for (auto& tri : f) {
      const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
      nf.push_back({tri[0], a, c});
      nf.push_back({tri[1], b, a});
      nf.push_back({tri[2], c, b});
      nf.push_back({a, b, c});
    }
    f.swap(nf);
  }
  Mesh m;
  std::vector<glm::vec3> verts;
  for (auto& p : v) verts.push_back(glm::vec3(p));
  std::vector<std::array<int, 3>> tris;
  for (auto& tri : f) tris.push_back({tri[0], tri[1], tri[2]});
  buildTriMesh(std::move(verts), std::move(tris), m);
  m.report.file = "generated:icosphere-" + std::to_string(level);
  finalizeMesh(m);
  return m;
}

Mesh torus(int nu, int nv) {
  Mesh m;
  std::vector<glm::vec3> verts(size_t(nu) * size_t(nv));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      const double r = 1.0 + 0.35 * std::cos(v);
      verts[size_t(i) * size_t(nv) + size_t(j)] =
          glm::vec3(float(r * std::cos(u) / 1.35), float(0.35 * std::sin(v) / 1.35), float(r * std::sin(u) / 1.35));
    }
  auto at = [&](int i, int j) { return (((i + nu) % nu) * nv + (j + nv) % nv); };
  std::vector<std::array<int, 3>> tris;
  tris.reserve(size_t(nu) * size_t(nv) * 2);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      tris.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      tris.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  buildTriMesh(std::move(verts), std::move(tris), m);
  m.report.file = "generated:torus-" + std::to_string(2 * nu * nv);
  finalizeMesh(m);
  return m;
}

Mesh cylinder(int nu, int nv) {
  Mesh m;
  std::vector<glm::vec3> verts;
  for (int i = 0; i <= nu; ++i)  // i = nu repeats i = 0's positions: the seam
    for (int j = 0; j <= nv; ++j) {
      const double u = 2 * M_PI * (i % nu) / nu;
      verts.push_back(glm::vec3(float(0.5 * std::cos(u)), float(-0.75 + 1.5 * j / nv), float(-0.5 * std::sin(u))));
    }
  auto at = [&](int i, int j) { return i * (nv + 1) + j; };
  std::vector<std::array<int, 3>> tris;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      tris.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      tris.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  buildTriMesh(std::move(verts), std::move(tris), m);
  m.report.file = "generated:cylinder";
  finalizeMesh(m);
  return m;
}

Mesh ellipsoid(int nu, int nv, const glm::vec3& radii) {
  Mesh m;
  std::vector<glm::vec3> verts{glm::vec3(0, radii.y, 0)};
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * M_PI * i / nu, v = M_PI * j / nv;
      verts.push_back(glm::vec3(float(radii.x * std::sin(v) * std::cos(u)), float(radii.y * std::cos(v)),
                                float(-radii.z * std::sin(v) * std::sin(u))));
    }
  verts.push_back(glm::vec3(0, -radii.y, 0));
  const int south = int(verts.size()) - 1;
  auto at = [&](int i, int j) { return 1 + (j - 1) * nu + (i % nu); };  // j in [1, nv)
  std::vector<std::array<int, 3>> tris;
  for (int i = 0; i < nu; ++i) {
    tris.push_back({0, at(i, 1), at(i + 1, 1)});
    for (int j = 1; j + 1 < nv; ++j) {
      tris.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      tris.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
    tris.push_back({at(i, nv - 1), south, at(i + 1, nv - 1)});
  }
  buildTriMesh(std::move(verts), std::move(tris), m);
  m.report.file = "generated:ellipsoid";
  finalizeMesh(m);
  return m;
}

std::optional<Mesh> generatedMesh(const std::string& name) {
  if (name == "generated:cylinder") return cylinder(96, 48);
  if (name == "generated:ellipsoid") return ellipsoid(128, 64, glm::vec3(1.0f, 0.7f, 0.45f));
  if (name == "generated:torus-871k") return torus(660, 660);
  if (name == "generated:torus-500k") return torus(500, 500);
  const std::string ico = "generated:icosphere-";
  if (name.rfind(ico, 0) == 0) {
    const int level = std::atoi(name.c_str() + ico.size());
    if (level >= 0 && level <= 9) return icosphere(level);
  }
  return std::nullopt;
}

}  // namespace npr
