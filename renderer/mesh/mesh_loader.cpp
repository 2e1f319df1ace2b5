// Mesh file loading (see mesh_loader.h): OBJ through our own parser (obj_parser.h), PLY,
// OFF, STL and OM through OpenMesh's readers, then the same building and finalising.
#include "renderer/mesh/mesh_loader.h"

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <sstream>

#include "renderer/core/elapsed.h"
#include "renderer/core/json.h"
#include "renderer/mesh/mesh_builder.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/mesh/obj_parser.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

Result<Mesh> loadWithOpenMesh(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Error{path + ": no such file"};
  if (fs::is_directory(path, ec)) return Error{path + ": is a directory, not a mesh file"};
  if (fs::file_size(path, ec) == 0) return Error{path + ": the file is empty"};
  Mesh m;
  m.report.file = path;
  TriMesh raw;
  OpenMesh::IO::Options opt;
  auto& errlog = omerr();
  errlog.disable();
  const bool ok = OpenMesh::IO::read_mesh(raw, path, opt);
  errlog.enable();
  if (!ok) return Error{path + ": OpenMesh could not read this file (corrupt, or not the format its extension says)"};
  if (raw.n_faces() == 0) return Error{path + ": contains no faces; nothing to draw"};
  std::vector<glm::dvec3> pts(raw.n_vertices());
  for (auto v : raw.vertices()) {
    const auto& p = raw.point(v);
    pts[static_cast<size_t>(v.idx())] = {p[0], p[1], p[2]};
  }
  std::vector<std::array<int, 3>> tris;
  tris.reserve(raw.n_faces());
  for (auto f : raw.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : raw.fv_range(f)) if (k < 3) t[static_cast<size_t>(k++)] = v.idx();
    tris.push_back(t);
  }
  m.report.warnings.push_back("read through OpenMesh's " + fs::path(path).extension().string() +
                              " reader: coordinates are single precision and faces it refused are not counted");
  std::vector<glm::vec3> verts = normalizePositions(pts, nullptr, m.report);
  buildTriMesh(verts, tris, m);
  return m;
}

}  // namespace

std::string LoadReport::toJson() const {
  std::ostringstream o;
  o << "{\"file\":" << json::string(file) << ",\"vertices\":" << vertices << ",\"triangles\":" << triangles
    << ",\"polygons_triangulated\":" << polygons_triangulated << ",\"skipped_faces\":" << skipped_faces
    << ",\"non_manifold_faces\":" << non_manifold_faces << ",\"warnings\":[";
  for (size_t i = 0; i < warnings.size(); ++i) o << (i ? "," : "") << json::string(warnings[i]);
  o << "],\"load_ms\":" << json::number(load_ms, "%.3f") << "}";
  return o.str();
}

Result<Mesh> loadMesh(const std::string& path) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  Result<Mesh> m = Error{""};
  if (ext == ".obj") m = loadObj(path);
  else if (ext == ".ply" || ext == ".off" || ext == ".stl" || ext == ".om") m = loadWithOpenMesh(path);
  else {
    std::error_code ec;
    if (!fs::exists(path, ec)) return Error{path + ": no such file"};
    if (fs::is_directory(path, ec)) return Error{path + ": is a directory, not a mesh file"};
    return Error{path + ": unsupported mesh format '" + ext + "' (use .obj, .ply, .off, .stl or .om)"};
  }
  if (!m) return m;
  finalizeMesh(*m);
  m->report.load_ms = msSince(t0);
  return m;
}

Result<Mesh> loadModel(const std::string& nameOrPath) {
  if (std::optional<Mesh> generated = generatedMesh(nameOrPath)) return std::move(*generated);
  return loadMesh(nameOrPath);
}

}  // namespace npr
