// The OM reader (see mesh_formats.h). OM is OpenMesh's own binary format and only its reader
// knows every version of it, but that reader asserts or crashes on corrupt files (a bad vertex
// chunk aborts the process). So it runs in a child process: the child reads the file with
// OpenMesh and sends positions and faces back through a pipe; the parent checks what arrives
// and builds the mesh like every other format. A child that crashes, runs out of memory or
// takes too long costs the user a message, not the scene. What it may cost is bounded by the
// file: before the child starts, the header's counts and every chunk's declared size are
// checked against the bytes the file has; the child's memory and time grow with the file's
// size from a small floor; and it checks the file's connectivity before walking it.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>

#include "renderer/core/input_file.h"
#include "renderer/core/printable.h"
#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/polygon_soup.h"

namespace npr {
namespace {
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

// The child's exit statuses beyond 0 (a mesh sent).
enum ChildStatus { kUnreadable = 2, kPipeClosed = 3, kOutOfMemory = 4, kBrokenConnectivity = 5 };

// What the child may use beyond what it shares with the parent at the fork: a floor, and a
// multiple of the file's size (OpenMesh keeps about 40 bytes per vertex and 12 per halfedge,
// from 12 and 6 bytes of the file; the child's copy to send doubles the vertices). A file of
// N bytes that needs more is corrupt.
constexpr std::uint64_t kChildMemoryFloor = 64ull << 20;
constexpr std::uint64_t kChildMemoryPerByte = 64;
// And the time: a floor, and the file at a pace far below OpenMesh's (over 50 MB/s here).
constexpr double kChildSecondsFloor = 2.0;
constexpr double kChildBytesPerSecond = 5e6;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

bool writeAll(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

// In the child: read with OpenMesh, send [nv][nf][nv x 3 doubles][per face: n, n indices].
// The address space this process has mapped now (the fork's share of the parent's), from
// /proc/self/statm; 0 where it cannot be read.
std::uint64_t mappedBytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  if (!(statm >> pages)) return 0;
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

// OpenMesh takes a version 2 file's connectivity (each halfedge's next, vertex and face, each
// face's halfedge) as stored, unchecked: a corrupt one sends a circulator round a loop that
// never closes, for as long as memory lasts (a 118-byte file took 5 s and 2 GB before this).
// So every handle is checked to be in range and every face's loop to close within the
// halfedges there are, before anything walks it.
bool connectivityConsistent(const OmMesh& mesh) {
  const long long nh = static_cast<long long>(mesh.n_halfedges()), nv = static_cast<long long>(mesh.n_vertices()),
                  nf = static_cast<long long>(mesh.n_faces());
  for (long long i = 0; i < nh; ++i) {
    const OpenMesh::HalfedgeHandle h(static_cast<int>(i));
    const int next = mesh.next_halfedge_handle(h).idx(), to = mesh.to_vertex_handle(h).idx(), face = mesh.face_handle(h).idx();
    if (next < 0 || next >= nh || to < 0 || to >= nv || face >= nf) return false;  // face -1: a boundary
  }
  for (long long f = 0; f < nf; ++f) {
    const OpenMesh::HalfedgeHandle start = mesh.halfedge_handle(OpenMesh::FaceHandle(static_cast<int>(f)));
    if (start.idx() < 0 || start.idx() >= nh) return false;
    OpenMesh::HalfedgeHandle h = start;
    long long steps = 0;
    do {
      if (mesh.face_handle(h).idx() != f || ++steps > nh) return false;
      h = mesh.next_halfedge_handle(h);
    } while (h != start);
  }
  return true;
}

[[noreturn]] void childRead(const std::string& path, int fd, std::uint64_t memory, int cpuSeconds) {
  // A crash in OpenMesh must end the child, not run the parent's handlers (a fuzzer's or a
  // sanitizer's) in it.
  for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) ::signal(sig, SIG_DFL);
  // OpenMesh's assertion text would only confuse: the parent says what happened.
  if (const int devnull = ::open("/dev/null", O_WRONLY); devnull >= 0) ::dup2(devnull, 2);
  if (!kAddressSanitizer) {  // ASan reserves terabytes of address space up front
    const rlim_t as = static_cast<rlim_t>(mappedBytes() + memory);
    const rlimit lim{as, as};
    setrlimit(RLIMIT_AS, &lim);
  }
  const rlimit cpu{static_cast<rlim_t>(cpuSeconds), static_cast<rlim_t>(cpuSeconds) + 1};
  setrlimit(RLIMIT_CPU, &cpu);
  int status = kUnreadable;
  try {
    OmMesh mesh;
    OpenMesh::IO::Options opt;
    omerr().disable();
    omlog().disable();
    if (!OpenMesh::IO::read_mesh(mesh, path, opt)) {
      status = kUnreadable;
    } else if (!connectivityConsistent(mesh)) {
      status = kBrokenConnectivity;
    } else {
      std::vector<std::uint32_t> out;
      const std::uint64_t head[2] = {mesh.n_vertices(), mesh.n_faces()};
      bool ok = writeAll(fd, head, sizeof head);
      std::vector<double> pts;
      pts.reserve(mesh.n_vertices() * 3);
      for (auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        pts.insert(pts.end(), {double(p[0]), double(p[1]), double(p[2])});
      }
      ok = ok && writeAll(fd, pts.data(), pts.size() * sizeof(double));
      for (auto f : mesh.faces()) {
        out.clear();
        out.push_back(0);
        for (auto v : mesh.fv_range(f)) out.push_back(static_cast<std::uint32_t>(v.idx()));
        out[0] = static_cast<std::uint32_t>(out.size() - 1);
        ok = ok && writeAll(fd, out.data(), out.size() * sizeof(std::uint32_t));
      }
      status = ok ? 0 : kPipeClosed;
    }
  } catch (...) {
    status = kOutOfMemory;  // std::bad_alloc from an absurd count, above all
  }
  ::close(fd);
  ::_exit(status);
}

// OpenMesh's reader believes the header's counts and each chunk's (it reserves and loops over
// them), so they are checked against the file first. OM's header is "OM", the mesh kind (T, Q
// or P), a version byte (major << 5 | minor) and three little-endian uint32 counts (vertices,
// faces, edges). Then chunks, each a little-endian uint16 header (bit 1: named; bits 2-4: the
// element kind; 5-8: the data's type; 10: floating point; 11-13: dimensions - 1; 14-15: the
// scalar's size), the name (a length byte and its characters), and the data: one value per
// element of its kind, or for a custom property (from version 2.2 after a type name like the
// name) a uint32 byte count and those bytes. These sizes are the ones OpenMesh 9's writer
// gives every kind of chunk it writes (positions in float or double, normals, texture
// coordinates, colours in bytes or floats, status, topology, custom properties: tested). A
// chunk whose size this does not know (an old version's polygon faces, an unknown type) ends
// the check: the child's bounds (what it may use grows with the file) cover the rest.
class OmFileCheck {
 public:
  OmFileCheck(const std::string& path, std::uintmax_t size) : path_(path), size_(size), in_(path, std::ios::binary) {}

  Status run() {
    if (!in_) return Error{printable(path_) + ": cannot be opened for reading (permissions?)"};
    unsigned char h[16] = {};
    if (!read(h, sizeof h) || h[0] != 'O' || h[1] != 'M') return Error{printable(path_) + ": not an OM file (it does not start with 'OM')"};
    if (h[2] != 'T' && h[2] != 'Q' && h[2] != 'P')
      return Error{printable(path_) + ": not an OM mesh (its kind byte is " + std::to_string(h[2]) + ", not T, Q or P)"};
    version_ = h[3];
    nv_ = le(h + 4, 4), nf_ = le(h + 8, 4), ne_ = le(h + 12, 4);
    // A vertex's position alone takes 12 bytes (three floats), a face or an edge at least one.
    if (nv_ * 12 + nf_ + ne_ > size_)
      return Error{printable(path_) + ": its header declares " + std::to_string(nv_) + " vertices, " + std::to_string(nf_) + " faces and " +
                   std::to_string(ne_) + " edges, more than its " + std::to_string(size_) + " bytes can hold: the file is corrupt or cut short"};
    for (int chunk = 1; at_ < size_; ++chunk) {
      unsigned char ch[2];
      if (!read(ch, 2)) return cut(chunk, "its header");
      const unsigned bits = unsigned(le(ch, 2));
      const unsigned entity = (bits >> 2) & 7u, type = (bits >> 5) & 15u, isFloat = (bits >> 10) & 1u, dims = ((bits >> 11) & 7u) + 1;
      const unsigned scalar = (bits >> 14) & 3u;
      if (entity == 7) return okStatus();  // the sentinel: the end
      if ((bits >> 1) & 1u)
        if (Status st = skipString(chunk, "its name"); !st) return st;
      std::uint64_t count = 0;
      switch (entity) {
        case 0: count = nv_; break;
        case 1: count = 1; break;
        case 2: count = nf_; break;
        case 4: count = ne_; break;
        case 6: count = 2 * ne_; break;
        default: return Error{printable(path_) + ": chunk " + std::to_string(chunk) + " is of an unknown kind of element (" + std::to_string(entity) + "): the file is corrupt"};
      }
      const std::uint64_t index = std::uint64_t(1) << scalar;  // topology: 1, 2, 4 or 8 bytes an index
      std::uint64_t bytes = 0;
      if (type == 6) {  // a custom property
        if (version_ >= (2u << 5 | 2u))
          if (Status st = skipString(chunk, "its type name"); !st) return st;
        unsigned char n[4];
        if (!read(n, 4)) return cut(chunk, "its size");
        bytes = le(n, 4);
      } else if (type == 7) {  // topology
        if (entity == 2 && version_ < (2u << 5)) return okStatus();  // an old version's faces: sized as they are read
        if (entity != 0 && entity != 2 && entity != 6) return okStatus();
        bytes = (entity == 6 ? ne_ * 6 : count) * index;
      } else if (type == 3) {  // status: a uint32 per element
        bytes = count * 4;
      } else if (type <= 4) {  // positions, normals, texture coordinates, colours
        bytes = count * dims * (isFloat ? std::uint64_t(4) << scalar : index);
      } else {
        return okStatus();  // a type this check does not know
      }
      if (bytes > size_ - at_)
        return Error{printable(path_) + ": chunk " + std::to_string(chunk) + " (" + what(entity, type) + ") declares " + std::to_string(bytes) +
                     " bytes where the file has " + std::to_string(size_ - at_) + " left: the file is corrupt or cut short"};
      at_ += bytes;
      in_.seekg(static_cast<std::streamoff>(at_));
    }
    return okStatus();
  }

 private:
  static std::uint64_t le(const unsigned char* p, int n) {
    std::uint64_t v = 0;
    for (int i = n - 1; i >= 0; --i) v = v << 8 | p[i];
    return v;
  }
  bool read(unsigned char* out, std::size_t n) {
    if (n > size_ - at_ || !in_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n))) return false;
    at_ += n;
    return true;
  }
  Status skipString(int chunk, const char* which) {
    unsigned char n = 0;
    if (!read(&n, 1) || n > size_ - at_) return cut(chunk, which);
    at_ += n;
    in_.seekg(static_cast<std::streamoff>(at_));
    return okStatus();
  }
  Status cut(int chunk, const char* where) const {
    return Error{printable(path_) + ": chunk " + std::to_string(chunk) + " is cut short in " + where + ": the file is corrupt or incomplete"};
  }
  static std::string what(unsigned entity, unsigned type) {
    static const char* const kinds[] = {"vertex", "mesh", "face", "?", "edge", "?", "halfedge", "?"};
    static const char* const types[] = {"positions", "normals", "texture coordinates", "status", "colours", "?", "custom property", "topology"};
    return std::string(kinds[entity & 7u]) + " " + (type < 8 ? types[type] : "data");
  }

  const std::string& path_;
  std::uint64_t size_;
  std::ifstream in_;
  std::uint64_t at_ = 0;
  unsigned version_ = 0;
  std::uint64_t nv_ = 0, nf_ = 0, ne_ = 0;
};

enum class ChildOutput { Complete, TimedOut, TooLarge };

// Reads the child's whole output, giving up after the time limit or past `maxBytes`.
ChildOutput readAllWithin(int fd, std::string& out, std::chrono::steady_clock::time_point deadline, std::size_t maxBytes) {
  char buf[1 << 16];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) return ChildOutput::TimedOut;
    pollfd pfd{fd, POLLIN, 0};
    const int r = ::poll(&pfd, 1, static_cast<int>(left));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return ChildOutput::TimedOut;
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return ChildOutput::Complete;  // end of the stream
    out.append(buf, static_cast<std::size_t>(n));
    if (out.size() > maxBytes) return ChildOutput::TooLarge;
  }
}

}  // namespace

Result<Mesh> loadOm(const std::string& path, int seconds) {
  Result<std::uintmax_t> size = checkInputFile(path, InputKind::Mesh);
  if (!size) return Error{size.error()};
  if (Status check = OmFileCheck(path, *size).run(); !check) return Error{check.error()};
  // What the child may use, by the file's size (the caller's time limit caps the time).
  const std::uint64_t memory = kChildMemoryFloor + kChildMemoryPerByte * std::uint64_t(*size);
  const double bounded = kChildSecondsFloor + double(*size) / kChildBytesPerSecond;
  const int limit = std::max(1, std::min(seconds, static_cast<int>(std::ceil(bounded))));
  int fds[2];
  if (::pipe(fds) != 0) return Error{path + ": cannot start the OM reader (pipe: " + std::strerror(errno) + ")"};
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return Error{path + ": cannot start the OM reader (fork: " + std::strerror(errno) + ")"};
  }
  if (pid == 0) {
    ::close(fds[0]);
    childRead(path, fds[1], memory, limit);
  }
  ::close(fds[1]);
  // Each vertex takes at least 12 bytes of the file and comes back as 24, each face at least
  // 4 and comes back as 16 for a triangle: more than 8 times the file means a corrupt count
  // that OpenMesh believed.
  const std::size_t maxBytes = static_cast<std::size_t>(*size) * 8 + 4096;
  std::string data;
  const ChildOutput got = readAllWithin(fds[0], data, std::chrono::steady_clock::now() + std::chrono::seconds(limit), maxBytes);
  ::close(fds[0]);
  if (got != ChildOutput::Complete) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if (got == ChildOutput::TimedOut)
    return Error{path + ": OpenMesh's OM reader took longer than " + std::to_string(limit) + " s, more than a file of its size needs; the file is refused"};
  if (got == ChildOutput::TooLarge) return Error{path + ": OpenMesh's OM reader made more of this file than it can hold: its counts are corrupt"};
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
    return Error{path + ": OpenMesh's OM reader took more than " + std::to_string(limit) + " s of processor time, more than a file of its size needs; the file is refused"};
  if (WIFSIGNALED(status))
    return Error{path + ": OpenMesh's OM reader crashed on this file (signal " + std::to_string(WTERMSIG(status)) + "): it is corrupt"};
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (code == kOutOfMemory)
      return Error{path + ": OpenMesh's OM reader needed more memory than a file of " + std::to_string(*size) + " bytes can: the file is corrupt"};
    if (code == kBrokenConnectivity)
      return Error{path + ": its connectivity is corrupt (a halfedge points outside the mesh, or a face's edges do not close into a loop)"};
    return Error{path + ": OpenMesh could not read this OM file (corrupt or an unknown version)"};
  }

  // The child's output is checked like any file: counts against the bytes that arrived.
  std::uint64_t nv = 0, nf = 0;
  if (data.size() < 16) return Error{path + ": the OM reader returned no mesh"};
  std::memcpy(&nv, data.data(), 8);
  std::memcpy(&nf, data.data() + 8, 8);
  std::size_t at = 16;
  if (nv > (data.size() - at) / 24) return Error{path + ": the OM reader returned an inconsistent mesh"};
  LoadReport report;
  report.file = path;
  Warnings warn(report.warnings);
  PolygonSoup soup;
  soup.vertices.reserve(nv);
  for (std::uint64_t i = 0; i < nv; ++i, at += 24) {
    glm::dvec3 p;
    std::memcpy(&p.x, data.data() + at, 24);
    if (!soup.addVertex(p)) warn.add(path + " vertex " + std::to_string(i) + ": non-finite coordinate; faces using it are skipped");
  }
  FaceBuilder faces(soup, report, warn);
  std::vector<long long> corners;
  for (std::uint64_t f = 0; f < nf; ++f) {
    std::uint32_t n = 0;
    if (data.size() - at < 4) return Error{path + ": the OM reader returned an inconsistent mesh"};
    std::memcpy(&n, data.data() + at, 4);
    at += 4;
    if (n > (data.size() - at) / 4) return Error{path + ": the OM reader returned an inconsistent mesh"};
    corners.clear();
    for (std::uint32_t k = 0; k < n; ++k, at += 4) {
      std::uint32_t idx = 0;
      std::memcpy(&idx, data.data() + at, 4);
      corners.push_back(idx);
    }
    faces.add(corners, "face", f);
  }
  warn.finish();
  return buildMesh(std::move(soup), std::move(report));
}

}  // namespace npr
