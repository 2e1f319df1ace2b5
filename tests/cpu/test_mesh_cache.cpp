// CPU tier: the on-disk mesh cache. A reload of an unchanged large model comes from the cache
// and equals the parsed mesh; a changed file, a damaged entry or an unwritable folder falls
// back to parsing; small models are never cached.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "renderer/mesh/mesh_cache.h"
#include "renderer/mesh/mesh_loader.h"
#include "support/test_util.h"

namespace npr {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

class MeshCache : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("XDG_CACHE_HOME", (dir.path() / "cache").c_str(), 1);
    unsetenv("NPR_NO_MESH_CACHE");
    model = (dir.path() / "torus.obj").string();
    test::writeObj(test::torus(300, 300), model);  // 180K triangles, about 7 MB
    ASSERT_GE(fs::file_size(model), kMinCachedBytes);
  }
  void TearDown() override { unsetenv("XDG_CACHE_HOME"); }
  static void expectSame(const Mesh& a, const Mesh& b) {
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_TRUE(a.positions == b.positions);
    EXPECT_TRUE(a.normals == b.normals);
    EXPECT_TRUE(a.indices == b.indices);
    EXPECT_TRUE(a.faceCentroids == b.faceCentroids);
    EXPECT_TRUE(a.faceNormals == b.faceNormals);
    EXPECT_EQ(a.radius, b.radius);
    EXPECT_EQ(a.closed, b.closed);
    EXPECT_EQ(a.report.triangles, b.report.triangles);
    EXPECT_EQ(a.report.warnings, b.report.warnings);
  }
  TempDir dir;
  std::string model;
};

TEST_F(MeshCache, UnchangedFileReloadsFromTheCacheIdentically) {
  auto parsed = loadMesh(model);
  ASSERT_TRUE(parsed) << parsed.error();
  EXPECT_FALSE(parsed->report.from_cache);
  EXPECT_TRUE(parsed->closed);  // kept in the entry, as the rest
  auto cached = loadMesh(model);
  ASSERT_TRUE(cached) << cached.error();
  EXPECT_TRUE(cached->report.from_cache);
  expectSame(*parsed, *cached);
  EXPECT_NE(cached->report.toJson().find("\"from_cache\":true"), std::string::npos);
}

TEST_F(MeshCache, AChangedFileIsParsedAgain) {
  ASSERT_TRUE(loadMesh(model));
  // Same size, new content and time: the entry must not be used.
  {
    std::fstream f(model, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(0);
    f << "#";
  }
  fs::last_write_time(model, fs::last_write_time(model) + std::chrono::seconds(5));
  auto again = loadMesh(model);
  ASSERT_TRUE(again) << again.error();
  EXPECT_FALSE(again->report.from_cache);
}

TEST_F(MeshCache, ADamagedEntryIsAMissNotACrash) {
  auto parsed = loadMesh(model);
  ASSERT_TRUE(parsed);
  for (const auto& e : fs::directory_iterator(meshCacheDir())) {
    const auto size = fs::file_size(e.path());
    fs::resize_file(e.path(), size / 2);  // truncated in the middle of an array
  }
  auto reloaded = loadMesh(model);
  ASSERT_TRUE(reloaded) << reloaded.error();
  EXPECT_FALSE(reloaded->report.from_cache);
  expectSame(*parsed, *reloaded);
  // Indices past the vertex count (bit rot, a hostile file): refused by the entry's checks.
  for (const auto& e : fs::directory_iterator(meshCacheDir())) {
    std::fstream f(e.path(), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(fs::file_size(e.path()) / 2));
    const std::string junk(64, '\xff');
    f.write(junk.data(), 64);
  }
  auto again = loadMesh(model);
  ASSERT_TRUE(again) << again.error();
  EXPECT_FALSE(again->report.from_cache);
}

TEST_F(MeshCache, UnwritableFolderAndSmallFilesStillLoad) {
  setenv("XDG_CACHE_HOME", "/proc/npr-no-such-folder", 1);
  auto m = loadMesh(model);
  ASSERT_TRUE(m) << m.error();
  EXPECT_FALSE(loadMesh(model)->report.from_cache);
  setenv("XDG_CACHE_HOME", (dir.path() / "cache").c_str(), 1);
  auto small = loadMesh(dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  ASSERT_TRUE(small);
  EXPECT_FALSE(loadMesh(dir.path().string() + "/t.obj")->report.from_cache);
  setenv("NPR_NO_MESH_CACHE", "1", 1);
  ASSERT_TRUE(loadMesh(model));
  EXPECT_FALSE(loadMesh(model)->report.from_cache);
  unsetenv("NPR_NO_MESH_CACHE");
}

}  // namespace
}  // namespace npr
