// Benchmark helpers (see bench_common.h).
#include "bench_common.h"

#include <sys/resource.h>

#include <filesystem>

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

double peakRssMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}

}  // namespace npr::bench
