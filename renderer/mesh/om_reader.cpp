// The OM reader (see mesh_formats.h). OM is OpenMesh's own binary format and only its reader
// knows every version of it, but that reader asserts or crashes on corrupt files (a bad vertex
// chunk aborts the process). So it runs in a child process: the child reads the file with
// OpenMesh and sends positions and faces back through a pipe; the parent checks what arrives
// and builds the mesh like every other format. A child that crashes, runs out of memory or
// takes too long costs the user a message, not the scene.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "renderer/core/input_file.h"
#include "renderer/core/printable.h"
#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/polygon_soup.h"

namespace npr {
namespace {


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
[[noreturn]] void childRead(const std::string& path, int fd) {
  // A crash in OpenMesh must end the child, not run the parent's handlers (a fuzzer's or a
  // sanitizer's) in it.
  for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) ::signal(sig, SIG_DFL);
  // OpenMesh's assertion text would only confuse: the parent says what happened.
  if (const int devnull = ::open("/dev/null", O_WRONLY); devnull >= 0) ::dup2(devnull, 2);
  if (!kAddressSanitizer) {  // ASan reserves terabytes of address space up front
    const rlimit lim{rlim_t(4) << 30, rlim_t(4) << 30};
    setrlimit(RLIMIT_AS, &lim);
  }
  int status = 2;
  try {
    OpenMesh::PolyMesh_ArrayKernelT<> mesh;
    OpenMesh::IO::Options opt;
    omerr().disable();
    omlog().disable();
    if (OpenMesh::IO::read_mesh(mesh, path, opt)) {
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
      status = ok ? 0 : 3;
    }
  } catch (...) {
    status = 4;  // std::bad_alloc from an absurd count, above all
  }
  ::close(fd);
  ::_exit(status);
}

// OpenMesh's reader believes the header's counts (it reserves and loops over them before the
// chunks say otherwise), so they are checked against the file's size first: OM's header is
// "OM", the mesh kind (T, Q or P), a version byte and three little-endian uint32 counts
// (vertices, faces, edges). A vertex's position alone takes 12 bytes (three floats) and a
// face or edge at least one byte, so a file smaller than that cannot hold what it declares.
Status checkOmHeader(const std::string& path, std::uintmax_t size) {
  unsigned char h[16] = {};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return Error{printable(path) + ": cannot be opened for reading (permissions?)"};
  const std::size_t got = std::fread(h, 1, sizeof h, f);
  std::fclose(f);
  if (got != sizeof h || h[0] != 'O' || h[1] != 'M') return Error{printable(path) + ": not an OM file (it does not start with 'OM')"};
  if (h[2] != 'T' && h[2] != 'Q' && h[2] != 'P')
    return Error{printable(path) + ": not an OM mesh (its kind byte is " + std::to_string(h[2]) + ", not T, Q or P)"};
  const auto count = [&](int at) {
    return std::uint64_t(h[at]) | std::uint64_t(h[at + 1]) << 8 | std::uint64_t(h[at + 2]) << 16 | std::uint64_t(h[at + 3]) << 24;
  };
  const std::uint64_t nv = count(4), nf = count(8), ne = count(12);
  if (nv * 12 + nf + ne > size)
    return Error{printable(path) + ": its header declares " + std::to_string(nv) + " vertices, " + std::to_string(nf) + " faces and " +
                 std::to_string(ne) + " edges, more than its " + std::to_string(size) + " bytes can hold: the file is corrupt or cut short"};
  return okStatus();
}

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
  if (Status header = checkOmHeader(path, *size); !header) return Error{header.error()};
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
    childRead(path, fds[1]);
  }
  ::close(fds[1]);
  // Each vertex takes at least 12 bytes of the file and comes back as 24, each face at least
  // 4 and comes back as 16 for a triangle: more than 8 times the file means a corrupt count
  // that OpenMesh believed.
  const std::size_t maxBytes = static_cast<std::size_t>(*size) * 8 + 4096;
  std::string data;
  const ChildOutput got = readAllWithin(fds[0], data, std::chrono::steady_clock::now() + std::chrono::seconds(seconds), maxBytes);
  ::close(fds[0]);
  if (got != ChildOutput::Complete) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if (got == ChildOutput::TimedOut) return Error{path + ": OpenMesh's OM reader took longer than " + std::to_string(seconds) + " s; the file is refused"};
  if (got == ChildOutput::TooLarge) return Error{path + ": OpenMesh's OM reader made more of this file than it can hold: its counts are corrupt"};
  if (WIFSIGNALED(status))
    return Error{path + ": OpenMesh's OM reader crashed on this file (signal " + std::to_string(WTERMSIG(status)) + "): it is corrupt"};
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return Error{path + (WIFEXITED(status) && WEXITSTATUS(status) == 4 ? ": OpenMesh's OM reader ran out of memory: the header is corrupt"
                                                                       : ": OpenMesh could not read this OM file (corrupt or an unknown version)")};

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
