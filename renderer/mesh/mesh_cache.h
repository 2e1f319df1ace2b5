// Loaded meshes kept on disk, so reopening an unchanged large file skips parsing and building
// (the 871K-triangle OBJ: about 0.8 s to load, about 0.15 s from the cache). One file per
// model under $XDG_CACHE_HOME/npr-viewer/meshes (~/.cache/... when unset), holding the Mesh's
// arrays and load report, keyed by the model's absolute path, size and modification time:
// any change, a different format version, or a cache file that fails its checks is a miss, and
// the model is loaded and cached again. Only models of at least kMinCachedBytes are cached:
// smaller ones load faster than the cache pays for.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "renderer/mesh/mesh.h"

namespace npr {

inline constexpr std::uintmax_t kMinCachedBytes = std::uintmax_t(4) << 20;

// The folder, from XDG_CACHE_HOME or HOME; empty (no caching) when neither is set or when
// NPR_NO_MESH_CACHE is set to anything but 0.
std::filesystem::path meshCacheDir();

// The cached mesh for `path` if its entry is present, current and intact.
std::optional<Mesh> readMeshCache(const std::string& path);
// Stores `mesh` for `path` (written to a temporary file and renamed, so a reader never sees
// half a file). Best effort: returns false when the folder cannot be written.
bool writeMeshCache(const std::string& path, const Mesh& mesh);

}  // namespace npr
