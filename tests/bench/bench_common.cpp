// Benchmark helpers (see bench_common.h).
#include "bench_common.h"

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "renderer/core/image_io.h"
#include "renderer/mesh/mesh_loader.h"

#include "support/test_util.h"

namespace npr::bench {

const Mesh& largeMesh() {
  static const Mesh m = test::torus(kTorusSide, kTorusSide);
  return m;
}

const std::string& largeObjPath() {
  static const std::string path = [] {
    const auto p = std::filesystem::temp_directory_path() / "npr-bench-torus-871k.obj";
    if (!std::filesystem::exists(p)) test::writeObj(test::torus(kTorusSide, kTorusSide), p.string());
    return p.string();
  }();
  return path;
}

const Mesh& largeMaterialMesh() {
  static const Mesh m = [] {
    const auto dir = std::filesystem::temp_directory_path() / "npr-bench-materials";
    const auto obj = dir / "torus-871k-materials.obj";
    if (!std::filesystem::exists(obj)) {
      std::filesystem::create_directories(dir);
      for (int t = 0; t < 4; ++t) {  // stripes, so the maps are not flat
        ImageRGBA8 img{512, 512, std::vector<std::uint8_t>(512 * 512 * 4, 255)};
        for (int y = 0; y < 512; ++y)
          for (int x = 0; x < 512; ++x) {
            std::uint8_t* px = &img.pixels[(std::size_t(y) * 512 + x) * 4];
            const bool dark = ((x + y * t) / 16) % 2;
            px[0] = std::uint8_t(dark ? 60 + 40 * t : 230);
            px[1] = std::uint8_t(dark ? 90 : 200 - 30 * t);
            px[2] = std::uint8_t(dark ? 40 : 150);
          }
        (void)writeImage((dir / ("map" + std::to_string(t) + ".png")).string(), img);
      }
      FILE* mtl = std::fopen((dir / "torus.mtl").c_str(), "w");
      for (int i = 0; i < 16; ++i) {
        const float u = float(i) / 16.0f;
        std::fprintf(mtl, "newmtl m%d\nKa %.3f %.3f 0.5\nKd %.3f %.3f 0.5\nKs %.2f %.2f %.2f\nNs %d\n", i, 0.3f + 0.6f * u,
                     0.8f - 0.5f * u, 0.3f + 0.6f * u, 0.8f - 0.5f * u, i % 3 ? 0.4f : 0.0f, i % 3 ? 0.4f : 0.0f,
                     i % 3 ? 0.4f : 0.0f, 8 + 4 * i);
        if (i % 4 == 0) std::fprintf(mtl, "map_Kd map%d.png\n", i / 4);
      }
      std::fclose(mtl);
      const Mesh t = test::torus(kTorusSide, kTorusSide);
      FILE* f = std::fopen(obj.c_str(), "w");
      std::fprintf(f, "mtllib torus.mtl\n");
      for (const auto& p : t.positions) std::fprintf(f, "v %.7f %.7f %.7f\n", p.x, p.y, p.z);
      for (const auto& p : t.positions) {
        const glm::vec3 d = glm::normalize(p);
        std::fprintf(f, "vt %.5f %.5f\n", 0.5f + std::atan2(d.z, d.x) / 6.2831853f * 4.0f, 0.5f + std::asin(d.y) / 3.14159265f * 4.0f);
      }
      int current = -1;
      for (size_t i = 0; i < t.indices.size(); i += 3) {
        const glm::vec3 c = t.faceCentroids[i / 3];
        const int mat = int((c.x + 1.0f) * 8.0f + (c.y + 1.0f) * 4.0f) % 16;
        if (mat != current) std::fprintf(f, "usemtl m%d\n", current = mat);
        const unsigned a = t.indices[i] + 1, b = t.indices[i + 1] + 1, cc = t.indices[i + 2] + 1;
        std::fprintf(f, "f %u/%u %u/%u %u/%u\n", a, a, b, b, cc, cc);
      }
      std::fclose(f);
    }
    Result<Mesh> loaded = loadMesh(obj.string());
    if (!loaded) {
      std::fprintf(stderr, "%s\n", loaded.error().c_str());
      std::abort();
    }
    return std::move(*loaded);
  }();
  return m;
}

std::unique_ptr<HeadlessContext> openBenchContext(int& exitStatus) {
  Result<GpuRequest> gpu = gpuRequestFromEnvironment();
  if (!gpu) {
    std::fprintf(stderr, "%s\n", gpu.error().c_str());
    exitStatus = 2;
    return nullptr;
  }
  Result<std::unique_ptr<HeadlessContext>> ctx = HeadlessContext::create(false, *gpu);
  if (!ctx) {
    std::fprintf(stderr, "%s\n", ctx.error().c_str());
    exitStatus = 1;
    return nullptr;
  }
  return std::move(*ctx);
}

double peakRssMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}

std::optional<ImageBenchArgs> parseImageBenchArgs(int argc, char** argv, const char* program) {
  ImageBenchArgs a;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) a.frames = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &a.width, &a.height);
    else if (!std::strcmp(argv[i], "--quick")) a.quick = true;
    else if (!std::strcmp(argv[i], "--objects") && i + 1 < argc) a.objects = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--size WxH] [--frames N] [--quick] [--objects N]\n", program);
      return std::nullopt;
    }
  }
  if (a.frames < 1 || a.width < 16 || a.height < 16 || a.objects < 0 || a.objects > 1000000) {
    std::fprintf(stderr, "%s: --frames must be positive, --size at least 16x16 and --objects 0..1000000\n", program);
    return std::nullopt;
  }
  return a;
}

}  // namespace npr::bench
