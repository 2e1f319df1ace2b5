// The on-disk mesh cache (see mesh_cache.h). Layout, little-endian as written by this machine:
// magic "NPRMESH", format version, the source's absolute path, size and mtime, the report's
// counts, centre, scale, the radius, whether the surface is closed, the warnings, then the arrays
// with their lengths.
#include "renderer/mesh/mesh_cache.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <vector>

namespace npr {
namespace fs = std::filesystem;
namespace {

constexpr char kMagic[8] = {'N', 'P', 'R', 'M', 'E', 'S', 'H', '\0'};
constexpr std::uint32_t kVersion = 3;  // 2: models with materials are no longer cached; 3: Mesh::closed

struct SourceKey {
  std::string path;
  std::uint64_t size = 0;
  std::int64_t mtime = 0;
};

std::optional<SourceKey> sourceKey(const std::string& path) {
  std::error_code ec;
  SourceKey k;
  k.path = fs::absolute(path, ec).lexically_normal().string();
  if (ec) return std::nullopt;
  k.size = fs::file_size(path, ec);
  if (ec) return std::nullopt;
  const auto t = fs::last_write_time(path, ec);
  if (ec) return std::nullopt;
  k.mtime = static_cast<std::int64_t>(t.time_since_epoch().count());
  return k;
}

fs::path entryFor(const SourceKey& key) {
  const fs::path dir = meshCacheDir();
  if (dir.empty()) return {};
  char name[32];
  std::snprintf(name, sizeof name, "%016zx.mesh", std::hash<std::string>{}(key.path));
  return dir / name;
}

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

class Writer {
 public:
  explicit Writer(std::FILE* f) : f_(f) {}
  template <class T>
  void pod(const T& v) { ok_ = ok_ && std::fwrite(&v, sizeof v, 1, f_) == 1; }
  void string(const std::string& s) {
    pod(static_cast<std::uint64_t>(s.size()));
    ok_ = ok_ && (s.empty() || std::fwrite(s.data(), 1, s.size(), f_) == s.size());
  }
  template <class T>
  void array(const std::vector<T>& v) {
    pod(static_cast<std::uint64_t>(v.size()));
    ok_ = ok_ && (v.empty() || std::fwrite(v.data(), sizeof(T), v.size(), f_) == v.size());
  }
  bool ok() const { return ok_; }

 private:
  std::FILE* f_;
  bool ok_ = true;
};

void prefault(void* data, std::size_t bytes);

// Reads the entry with every length checked against the bytes left before anything is
// allocated. (Mapping the file instead measured no faster: the time goes to first touches of
// the arrays' pages, about 130 ms for the 42 MB of the 871K-triangle mesh on this machine, and
// the mapping added its own pages to the peak.)
class Reader {
 public:
  Reader(std::FILE* f, std::uint64_t size) : f_(f), left_(size) {}
  template <class T>
  bool pod(T& v) { return take(sizeof v) && std::fread(&v, sizeof v, 1, f_) == 1; }
  bool string(std::string& s) {
    std::uint64_t n = 0;
    if (!pod(n) || n > left_) return false;
    s.resize(n);
    return take(n) && (n == 0 || std::fread(s.data(), 1, n, f_) == n);
  }
  template <class T>
  bool array(std::vector<T>& v) {
    std::uint64_t n = 0;
    if (!pod(n) || n > left_ / sizeof(T)) return false;
    v.reserve(n);
    prefault(v.data(), n * sizeof(T));
    v.resize(n);
    return take(n * sizeof(T)) && (n == 0 || std::fread(v.data(), sizeof(T), n, f_) == n);
  }
  bool atEnd() const { return left_ == 0; }

 private:
  bool take(std::uint64_t n) {
    if (n > left_) return false;
    left_ -= n;
    return true;
  }
  std::FILE* f_;
  std::uint64_t left_;
};

// Faults a fresh buffer's pages in with one call: on this project's virtual machines each
// first touch of a page costs microseconds, and touching 42 MB page by page took 130 ms.
// Only a hint: kernels before 5.14 refuse it and the pages are faulted in as they are written.
void prefault(void* data, std::size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  const std::uintptr_t page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
  if (end > begin) (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)data;
  (void)bytes;
#endif
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

fs::path meshCacheDir() {
  if (const char* off = std::getenv("NPR_NO_MESH_CACHE"); off && *off && std::strcmp(off, "0") != 0) return {};
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "npr-viewer" / "meshes";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "npr-viewer" / "meshes";
  return {};
}

std::optional<Mesh> readMeshCache(const std::string& path) {
  const std::optional<SourceKey> key = sourceKey(path);
  if (!key || key->size < kMinCachedBytes) return std::nullopt;
  const fs::path entry = entryFor(*key);
  std::error_code ec;
  const std::uintmax_t size = entry.empty() ? 0 : fs::file_size(entry, ec);
  if (entry.empty() || ec || !fs::is_regular_file(entry, ec)) return std::nullopt;
  File f(std::fopen(entry.c_str(), "rb"), &std::fclose);
  if (!f) return std::nullopt;
  Reader in(f.get(), size);
  char magic[8];
  std::uint32_t version = 0;
  SourceKey stored;
  if (!in.pod(magic) || std::memcmp(magic, kMagic, 8) != 0 || !in.pod(version) || version != kVersion) return std::nullopt;
  if (!in.string(stored.path) || !in.pod(stored.size) || !in.pod(stored.mtime)) return std::nullopt;
  if (stored.path != key->path || stored.size != key->size || stored.mtime != key->mtime) return std::nullopt;
  Mesh m;
  LoadReport& r = m.report;
  std::uint64_t counts[7];
  std::uint64_t nWarnings = 0;
  std::uint8_t closed = 0;
  if (!in.pod(counts) || !in.pod(r.original_centre) || !in.pod(r.original_scale) || !in.pod(m.radius) || !in.pod(closed) ||
      !in.pod(nWarnings) || closed > 1)
    return std::nullopt;
  m.closed = closed == 1;
  if (nWarnings > 1000) return std::nullopt;
  r.warnings.resize(nWarnings);
  for (std::string& w : r.warnings)
    if (!in.string(w)) return std::nullopt;
  if (!in.array(m.positions) || !in.array(m.normals) || !in.array(m.indices) || !in.array(m.faceCentroids) ||
      !in.array(m.faceNormals) || !in.atEnd())
    return std::nullopt;
  // The checks that make a damaged entry a miss instead of a crash in the renderer.
  const std::size_t nv = m.positions.size(), nf = m.indices.size() / 3;
  if (m.indices.size() % 3 || m.normals.size() != nv || m.faceCentroids.size() != nf || m.faceNormals.size() != nf) return std::nullopt;
  for (std::uint32_t i : m.indices)
    if (i >= nv) return std::nullopt;
  for (std::size_t i = 0; i < nv; ++i)
    if (!finite(m.positions[i]) || !finite(m.normals[i])) return std::nullopt;
  for (std::size_t i = 0; i < nf; ++i)
    if (!finite(m.faceCentroids[i]) || !finite(m.faceNormals[i])) return std::nullopt;
  r.file = path;
  r.vertices = counts[0];
  r.triangles = counts[1];
  r.polygons_triangulated = counts[2];
  r.skipped_faces = counts[3];
  r.repeated_corner_faces = counts[4];
  r.degenerate_triangles = counts[5];
  r.non_manifold_faces = counts[6];
  r.from_cache = true;
  return m;
}

bool writeMeshCache(const std::string& path, const Mesh& m) {
  // A model with materials depends on its .mtl and texture files too, which the key does not
  // cover: it is parsed each time.
  if (m.hasAppearance() || m.hasMarks()) return false;
  const std::optional<SourceKey> key = sourceKey(path);
  if (!key || key->size < kMinCachedBytes) return false;
  const fs::path entry = entryFor(*key);
  if (entry.empty()) return false;
  std::error_code ec;
  fs::create_directories(entry.parent_path(), ec);
  if (ec) return false;
  const fs::path tmp = entry.string() + ".tmp" + std::to_string(::getpid());
  {
    File f(std::fopen(tmp.c_str(), "wb"), &std::fclose);
    if (!f) return false;
    Writer out(f.get());
    const LoadReport& r = m.report;
    const std::uint64_t counts[7] = {r.vertices, r.triangles, r.polygons_triangulated, r.skipped_faces,
                                     r.repeated_corner_faces, r.degenerate_triangles, r.non_manifold_faces};
    out.pod(kMagic);
    out.pod(kVersion);
    out.string(key->path);
    out.pod(key->size);
    out.pod(key->mtime);
    out.pod(counts);
    out.pod(r.original_centre);
    out.pod(r.original_scale);
    out.pod(m.radius);
    out.pod(static_cast<std::uint8_t>(m.closed ? 1 : 0));
    out.pod(static_cast<std::uint64_t>(r.warnings.size()));
    for (const std::string& w : r.warnings) out.string(w);
    out.array(m.positions);
    out.array(m.normals);
    out.array(m.indices);
    out.array(m.faceCentroids);
    out.array(m.faceNormals);
    if (!out.ok() || std::fflush(f.get()) != 0) {
      f.reset();
      fs::remove(tmp, ec);
      return false;
    }
  }
  fs::rename(tmp, entry, ec);
  if (ec) fs::remove(tmp, ec);
  return !ec;
}

}  // namespace npr
