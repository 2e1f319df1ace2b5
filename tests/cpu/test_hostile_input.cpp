// CPU tier: hostile and degenerate files, each a regression test for a crash, hang or runaway
// allocation found by hand or by the fuzzers (tests/fuzz). Every one must come back as a mesh
// or palette the renderer can use, or as a message naming the file; none may abort.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "renderer/core/image_io.h"
#include "renderer/core/input_file.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/mesh/polygon_triangulation.h"
#include "renderer/palette/palette.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::TempDir;

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

void expectDrawable(const Mesh& m) {
  for (std::uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
  for (const auto& p : m.positions) {
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    ASSERT_LE(glm::length(p), 1.0f + 1e-4f);
  }
  for (const auto& n : m.normals) ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
}

TEST(HostileInput, FaceRepeatingACornerIsRepairedOrSkippedNeverHandedToOpenMesh) {
  TempDir d;
  // Both aborted the viewer in OpenMesh's add_face (assertion boundary_prev.is_valid()).
  auto m = loadMesh(d.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\nf 1 2 3\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), 1u);
  EXPECT_EQ(m->report.repeated_corner_faces, 1u);
  EXPECT_EQ(m->report.skipped_faces, 1u);
  auto single = loadMesh(d.write("b.obj", "v 0 0 0\nf 1 1 1\n"));
  ASSERT_FALSE(single);
  EXPECT_TRUE(contains(single.error(), "no face")) << single.error();
  // A repeat in a row is dropped and the rest of the face kept: a quad written with one corner
  // twice is still a quad.
  auto quad = loadMesh(d.write("c.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 2 3 4 4 1\n"));
  ASSERT_TRUE(quad) << quad.error();
  EXPECT_EQ(quad->triangleCount(), 2u);
  EXPECT_EQ(quad->report.repeated_corner_faces, 1u);
  // A polygon touching itself at a vertex: its zero-area triangles are counted, not drawn.
  auto touching = loadMesh(d.write("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 1 3\nf 1 2 4 2 3\n"));
  ASSERT_TRUE(touching) << touching.error();
  EXPECT_GE(touching->report.degenerate_triangles, 1u);
  expectDrawable(*touching);
}

TEST(HostileInput, RepeatedCornersInEveryFormatAreHandledAlike) {
  TempDir d;
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                          "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n3 0 1 2\n";
  const std::string off = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n3 0 1 2\n";
  for (const auto& [name, text] : {std::pair{"r.ply", ply}, std::pair{"r.off", off}}) {
    auto m = loadMesh(d.write(name, text));
    ASSERT_TRUE(m) << name << ": " << m.error();
    EXPECT_EQ(m->triangleCount(), 1u) << name;
    EXPECT_EQ(m->report.skipped_faces, 1u) << name;
  }
}

TEST(HostileInput, DevicesFifosAndOversizedFilesAreRefusedBeforeAnyRead) {
  TempDir d;
  const std::string fifo = (d.path() / "pipe.obj").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto m = loadMesh(fifo);  // reading it would block for ever
  ASSERT_FALSE(m);
  EXPECT_TRUE(contains(m.error(), "not a regular file")) << m.error();
  // A palette entry naming /dev/zero used to hang the viewer.
  auto p = loadPalette(d.write("dev.palette", "/dev/zero\n"));
  ASSERT_FALSE(p);
  EXPECT_TRUE(contains(p.error(), "line 1")) << p.error();
  EXPECT_TRUE(contains(p.error(), "not a regular file")) << p.error();
  auto pf = loadPalette((d.path() / "pipe.obj").string());
  ASSERT_FALSE(pf);
  // A sparse file past the model limit is refused from its size alone (nothing is read).
  const std::string big = (d.path() / "big.obj").string();
  { std::ofstream(big) << "v 0 0 0\n"; }
  std::filesystem::resize_file(big, kMaxModelFileBytes + 1);
  auto huge = loadMesh(big);
  ASSERT_FALSE(huge);
  EXPECT_TRUE(contains(huge.error(), "larger than")) << huge.error();
}

TEST(HostileInput, OwnReadersRefuseBrokenHeadersWithoutAllocating) {
  TempDir d;
  struct Case { const char* name; std::string text; const char* why; };
  const Case cases[] = {
      // Each crashed, flooded stderr, or allocated without bound in OpenMesh's readers.
      {"prop.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\nend_header\n", "before any 'element'"},
      {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", "end_header"},
      {"absurd.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
                     "property float z\nend_header\n\x01\x02", "header's element counts"},
      {"header.off", "OFF\n", "counts"},
      {"absurd.off", "OFF\n4000000000 1 0\n0 0 0\n", "cannot fit"},
      {"trunc.stl", std::string(80, 'x') + std::string("\xe8\x03\x00\x00", 4) + std::string(100, '\0'), "truncated"},
  };
  for (const Case& c : cases) {
    auto m = loadMesh(d.write(c.name, c.text));
    ASSERT_FALSE(m) << c.name;
    EXPECT_TRUE(contains(m.error(), c.name)) << m.error();
    EXPECT_TRUE(contains(m.error(), c.why)) << c.name << ": " << m.error();
  }
}

TEST(HostileInput, LargestVertexIndexIsNamedWithoutOverflow) {
  // Found by fuzz_off: a face naming vertex 9223372036854775807 (the largest long long)
  // overflowed while the warning added one for its one-based number.
  TempDir d;
  auto m = loadMesh(d.write("huge-index.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 9223372036854775807 2\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), 1u);
  bool named = false;
  for (const std::string& w : m->report.warnings) named = named || contains(w, "vertex 9223372036854775808");
  EXPECT_TRUE(named);
}

TEST(HostileInput, CorruptOmFileCostsAMessageNotTheProcess) {
  // Found by fuzz_om: OpenMesh's reader asserts on this file's vertex chunk (abort). It now
  // runs in a child process; this test's process must survive and get a message.
  auto m = loadMesh(std::string(NPR_SOURCE_DIR) + "/tests/fuzz/regressions/om/bad-vertex-chunk.om");
  ASSERT_FALSE(m);
  EXPECT_TRUE(contains(m.error(), "OM reader")) << m.error();
}

TEST(HostileInput, OmHeaderCountsBeyondTheFileAreRefusedBeforeOpenMeshReadsIt) {
  // A 118-byte OM file whose header declares billions of vertices, faces and edges kept
  // OpenMesh's reader (in its child) busy for seconds and gigabytes. The counts are checked
  // against the file's size first, so no child is started.
  TempDir d;
  std::string bytes = "OMTB";
  for (int k = 0; k < 3; ++k) bytes += std::string("\xf0\xff\xff\x0f", 4);
  bytes += std::string(118 - bytes.size(), '\0');
  const std::string path = d.write("absurd.om", bytes);
  auto m = loadMesh(path);
  ASSERT_FALSE(m);
  EXPECT_TRUE(contains(m.error(), "header declares 268435440 vertices")) << m.error();
  EXPECT_TRUE(contains(m.error(), "more than its 118 bytes can hold")) << m.error();
  EXPECT_FALSE(contains(m.error(), "OM reader")) << "the child was started: " << m.error();
  // A kind byte other than T, Q or P is not an OM mesh.
  auto kind = loadMesh(d.write("kind.om", std::string("OMXB") + std::string(14, '\0')));
  ASSERT_FALSE(kind);
  EXPECT_TRUE(contains(kind.error(), "kind byte is 88")) << kind.error();
}

TEST(HostileInput, OmConnectivityThatNeverClosesIsRefusedAtOnce) {
  // Two 118-byte files (issue 62) with honest counts and chunks whose sizes add up, but whose
  // halfedges point into loops that never close: walking a face's vertices went on until the
  // child's 4 GB ran out (5 s, 2.1 GB). The child now checks the connectivity first.
  for (const char* name : {"broken-connectivity-1.om", "broken-connectivity-2.om"}) {
    auto m = loadMesh(std::string(NPR_SOURCE_DIR) + "/tests/fuzz/regressions/om/" + name);
    ASSERT_FALSE(m) << name;
    EXPECT_TRUE(contains(m.error(), "connectivity is corrupt")) << name << ": " << m.error();
  }
}

TEST(HostileInput, OmChunksBeyondTheFileAreRefusedBeforeOpenMeshReadsIt) {
  // A valid file cut short: its last chunks declare more than the bytes left. Each chunk's size
  // is checked against the file before a child is started, and the message names the chunk.
  TempDir d;
  std::ifstream in(std::string(NPR_SOURCE_DIR) + "/tests/fuzz/corpus/om/cube.om", std::ios::binary);
  const std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(whole.size(), 250u);
  auto cut = loadMesh(d.write("cut.om", whole.substr(0, 200)));  // inside the halfedge topology
  ASSERT_FALSE(cut);
  EXPECT_TRUE(contains(cut.error(), "chunk 2 (halfedge topology) declares 108 bytes where the file has 84 left")) << cut.error();
  EXPECT_FALSE(contains(cut.error(), "OM reader")) << "the child was started: " << cut.error();
  // A custom property whose byte count runs past the end.
  std::string custom = whole.substr(0, 248);  // up to the sentinel
  custom += std::string("\xc2\x00\x04" "mass" "\x05" "float", 13);  // named, vertex, custom
  custom += std::string("\xff\xff\xff\x7f", 4);
  auto big = loadMesh(d.write("custom.om", custom));
  ASSERT_FALSE(big);
  EXPECT_TRUE(contains(big.error(), "chunk 5 (vertex custom property) declares 2147483647 bytes")) << big.error();
  // The whole file still reads.
  auto m = loadMesh(d.write("whole.om", whole));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), 12u);
}

TEST(HostileInput, CoordinatesNearTheDoubleRangeStayFiniteAndKeepTheShape) {
  TempDir d;
  // Centring (lo + hi) / 2 and the radius overflowed to inf, and every position became NaN.
  const char* shapes[] = {"v 1e308 0 0\nv -1e308 0 0\nv 0 1e308 0\nf 1 2 3\n",
                          "v 1.7e308 1.7e308 0\nv 1.6e308 1.7e308 0\nv 1.7e308 1.6e308 0\nf 1 2 3\n",
                          "v 1e-310 0 0\nv 0 1e-310 0\nv 0 0 0\nf 1 2 3\n"};
  int i = 0;
  for (const char* text : shapes) {
    auto m = loadMesh(d.write("huge" + std::to_string(i++) + ".obj", text));
    ASSERT_TRUE(m) << m.error();
    expectDrawable(*m);
    EXPECT_NEAR(m->radius, 1.0f, 1e-4f) << text;
    EXPECT_GT(glm::length(m->faceNormals[0]), 0.99f) << text;  // not collapsed to a point or a line
  }
  // The same through the STL reader (single precision: 3e38 is near float's range).
  std::string stl = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 3e38 0 0\nvertex -3e38 0 0\nvertex 0 3e38 0\nendloop\nendfacet\nendsolid\n";
  auto s = loadMesh(d.write("huge.stl", stl));
  ASSERT_TRUE(s) << s.error();
  expectDrawable(*s);
}

TEST(HostileInput, EarClippingCostIsBoundedAndCoverageKept) {
  // A comb: n teeth give n reflex corners, the case that made the old clipper O(n^3)
  // (seconds for a few thousand corners). Count point-in-triangle tests instead of timing.
  const int teeth = 1500;
  std::vector<glm::dvec3> poly;
  for (int i = 0; i < teeth; ++i) {
    poly.push_back({2.0 * i, 0.0, 0.0});
    poly.push_back({2.0 * i + 1.0, 10.0, 0.0});
  }
  poly.push_back({2.0 * teeth, -5.0, 0.0});
  poly.push_back({0.0, -5.0, 0.0});
  const double n = double(poly.size());
  TriangulationBudget budget;
  const std::int64_t start = budget.tests;
  const std::vector<int> tris = triangulatePolygon(poly, budget);
  EXPECT_EQ(tris.size(), (poly.size() - 2) * 3);
  EXPECT_LT(double(start - budget.tests), n * n) << "ear tests should be O(n r), not O(n^3)";
  // With the budget spent, the rest is fanned: still n - 2 triangles, and it returns at once.
  TriangulationBudget spent{0};
  EXPECT_EQ(triangulatePolygon(poly, spent).size(), (poly.size() - 2) * 3);
}

TEST(HostileInput, LargeImagesAreReducedWhileReadKeepingTheTone) {
  TempDir d;
  ImageRGBA8 img{64, 48, std::vector<std::uint8_t>(64 * 48 * 4)};
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      std::uint8_t* p = &img.pixels[(static_cast<size_t>(y) * 64 + x) * 4];
      p[0] = p[1] = p[2] = ((x / 2 + y / 2) % 2) ? 255 : 0;  // a 2-pixel checker: half the light
      p[3] = 255;
    }
  const std::string path = d.path().string() + "/checker.png";
  ASSERT_TRUE(writeImage(path, img));
  auto size = readImageSize(path);
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 64);
  auto small = loadImage(path, {16, 12});
  ASSERT_TRUE(small) << small.error();
  EXPECT_EQ(small->width, 16);
  EXPECT_EQ(small->height, 12);
  // Averaged in linear light: half the light is encoded 188, not the 128 of averaging codes.
  for (std::size_t i = 0; i < small->pixels.size(); i += 4) {
    EXPECT_NEAR(small->pixels[i], 188, 2);
    EXPECT_EQ(small->pixels[i + 3], 255);
  }
}

TEST(HostileInput, PngChunkLongerThanTheFileIsRefusedBeforeDecoding) {
  // libpng allocates a chunk's declared length before reading it: the fuzzer's file of 316
  // bytes made it allocate 1.8 GB. The chunks are checked against the file first.
  const std::string found = std::string(NPR_SOURCE_DIR) + "/tests/fuzz/regressions/image/png-chunk-longer-than-the-file.png";
  auto size = readImageSize(found);
  ASSERT_FALSE(size);
  EXPECT_TRUE(contains(size.error(), "corrupt PNG: chunk")) << size.error();
  // A valid PNG with its image data's length field raised.
  TempDir d;
  const std::string path = d.path().string() + "/long-chunk.png";
  ASSERT_TRUE(writeImage(path, ImageRGBA8{8, 8, std::vector<std::uint8_t>(8 * 8 * 4, 200)}));
  std::string bytes;
  {
    std::ifstream f(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(f), {});
  }
  ASSERT_TRUE(loadImage(path, {8, 8}));
  const std::size_t idat = bytes.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  bytes[idat - 4] = char(0x6c);
  {
    std::ofstream f(path, std::ios::binary);
    f << bytes;
  }
  auto img = loadImage(path, {8, 8});
  ASSERT_FALSE(img);
  EXPECT_TRUE(contains(img.error(), "chunk 'IDAT' at byte " + std::to_string(idat - 4))) << img.error();
  EXPECT_TRUE(contains(img.error(), "long-chunk.png")) << img.error();
}

TEST(HostileInput, PaletteDeclaringTooManyPixelsIsRefusedBeforeDecoding) {
  TempDir d;
  // A 16384 x 16384 grey PNG of zeros is about 260 KB; five of them declare 1.3 gigapixels.
  // Listed 256 times this used to end in an uncaught std::bad_alloc.
  ImageRGBA8 tiny{1, 1, {0, 0, 0, 255}};
  ASSERT_TRUE(writeImage(d.path().string() + "/tiny.png", tiny));
  // Stand in for a huge image: the header is all that is read, so write one by hand.
  const std::string big = d.path().string() + "/big.tga";
  {
    std::ofstream f(big, std::ios::binary);
    const unsigned char header[18] = {0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x00, 0x40, 0x00, 0x40, 8, 0};  // 16384 x 16384 grey
    f.write(reinterpret_cast<const char*>(header), 18);
    f.write("\0\0\0\0", 4);
  }
  std::string list;
  for (int i = 0; i < 256; ++i) list += "big.tga\n";
  auto p = loadPalette(d.write("huge.palette", list));
  ASSERT_FALSE(p);
  EXPECT_TRUE(contains(p.error(), "megapixels")) << p.error();
}

}  // namespace
}  // namespace npr
