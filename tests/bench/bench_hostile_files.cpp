// What refusing or reading small hostile files costs: every file of the given folders (by
// default the OM fuzz corpus and regressions, and a campaign's corpus and findings where
// build-fuzz/ has them) under a size limit is loaded as the viewer loads it, and the wall
// time of each load and the peak resident memory of the readers' child processes (OM's) are
// printed, with the largest of each. A file of under 1 KB should cost under 0.2 s and 64 MB.
// Run: build/tests/bench/bench_hostile_files [--max-bytes N] [DIR...]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/mesh/mesh_loader.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  std::uintmax_t maxBytes = 1024;
  std::vector<std::string> dirs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--max-bytes" && i + 1 < argc) maxBytes = std::strtoull(argv[++i], nullptr, 10);
    else dirs.push_back(a);
  }
  const std::string root = NPR_SOURCE_DIR;
  if (dirs.empty())
    dirs = {root + "/tests/fuzz/corpus/om", root + "/tests/fuzz/regressions/om", root + "/build-fuzz/corpus/om", root + "/build-fuzz/findings/om"};
  std::size_t files = 0, refused = 0;
  double slowest = 0.0;
  std::string slowestName;
  for (const std::string& dir : dirs) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::vector<fs::path> paths;
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (e.is_regular_file() && e.file_size() <= maxBytes) paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    for (const fs::path& p : paths) {
      // The loader picks the reader by extension: a fuzzer's artifact has none.
      const fs::path named = fs::temp_directory_path() / "bench-hostile-file.om";
      fs::copy_file(p, named, fs::copy_options::overwrite_existing, ec);
      const auto t0 = std::chrono::steady_clock::now();
      const auto m = npr::loadMesh(named.string());
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      ++files;
      refused += m ? 0 : 1;
      if (s > slowest) slowest = s, slowestName = p.string();
    }
  }
  rusage children{};
  getrusage(RUSAGE_CHILDREN, &children);
  std::printf("%zu files of at most %ju bytes (%zu refused, %zu read)\n", files, maxBytes, refused, files - refused);
  std::printf("slowest load: %.3f s (%s)\n", slowest, slowestName.c_str());
  std::printf("largest reader child: %.1f MB resident at its peak\n", double(children.ru_maxrss) / 1024.0);
  return 0;
}
