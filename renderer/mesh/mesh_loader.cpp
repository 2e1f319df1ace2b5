// Mesh file loading (see mesh_loader.h): dispatch by extension to our readers (obj_parser.h,
// mesh_formats.h), then the same finalising.
#include "renderer/mesh/mesh_loader.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <sstream>

#include "renderer/core/elapsed.h"
#include "renderer/core/json.h"
#include "renderer/core/input_file.h"
#include "renderer/mesh/mesh_cache.h"
#include "renderer/mesh/polygon_soup.h"
#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/mesh/obj_parser.h"

namespace npr {
namespace fs = std::filesystem;
std::string LoadReport::toJson() const {
  std::ostringstream o;
  o << "{\"file\":" << json::string(file) << ",\"vertices\":" << vertices << ",\"triangles\":" << triangles
    << ",\"polygons_triangulated\":" << polygons_triangulated << ",\"skipped_faces\":" << skipped_faces
    << ",\"repeated_corner_faces\":" << repeated_corner_faces << ",\"degenerate_triangles\":" << degenerate_triangles
    << ",\"non_manifold_faces\":" << non_manifold_faces << ",\"warnings\":[";
  for (size_t i = 0; i < warnings.size(); ++i) o << (i ? "," : "") << json::string(warnings[i]);
  auto list = [&](const char* name, const std::vector<std::string>& v) {
    o << ",\"" << name << "\":[";
    for (size_t i = 0; i < v.size(); ++i) o << (i ? "," : "") << json::string(v[i]);
    o << "]";
  };
  o << "]";
  list("material_libraries", material_libraries);
  o << ",\"materials\":" << materials;
  list("textures_loaded", textures_loaded);
  list("textures_missing", textures_missing);
  o << ",\"vertex_colours\":" << (vertex_colours ? "true" : "false")
    << ",\"texture_coordinates\":" << (texture_coordinates ? "true" : "false");
  o << ",\"load_ms\":" << json::number(load_ms, "%.3f") << ",\"from_cache\":" << (from_cache ? "true" : "false") << "}";
  return o.str();
}

Result<Mesh> loadMesh(const std::string& path) {
  const auto t0 = std::chrono::steady_clock::now();
  if (Result<std::uintmax_t> f = checkInputFile(path, InputKind::Mesh); !f) return Error{f.error()};
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  Result<Mesh> (*parse)(const std::string&, std::string) = nullptr;
  if (ext == ".obj") parse = parseObj;
  else if (ext == ".ply") parse = parsePly;
  else if (ext == ".off") parse = parseOff;
  else if (ext == ".stl") parse = parseStl;
  else if (ext == ".gltf" || ext == ".glb") parse = parseGltf;
  else if (ext != ".om") return Error{path + ": unsupported mesh format '" + ext + "' (use .obj, .gltf, .glb, .ply, .off, .stl or .om)"};
  // glTF names other files (buffers, images) that the cache's key does not cover.
  // --verbose wants every warning, which the cache (holding the summed ones) does not keep.
  const bool cacheable = parse != parseGltf && !WarningDetail::all();
  if (std::optional<Mesh> cached = cacheable ? readMeshCache(path) : std::nullopt) {
    cached->report.load_ms = msSince(t0);
    return std::move(*cached);
  }
  Result<Mesh> m = Error{""};
  if (parse) {
    Result<std::string> bytes = readInputFile(path, InputKind::Mesh);
    if (!bytes) return Error{bytes.error()};
    if (bytes->empty()) return Error{path + ": the file is empty"};
    m = parse(path, std::move(*bytes));
  } else {
    m = loadOm(path);
  }
  if (!m) return m;
  finalizeMesh(*m);
  m->report.load_ms = msSince(t0);
  if (cacheable) (void)writeMeshCache(path, *m);  // best effort: a read-only cache folder only costs the next load time
  return m;
}

Result<Mesh> loadModel(const std::string& nameOrPath) {
  if (std::optional<Mesh> generated = generatedMesh(nameOrPath)) return std::move(*generated);
  return loadMesh(nameOrPath);
}

}  // namespace npr
