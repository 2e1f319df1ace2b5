// Finding the shipped data (see data_directory.h).
#include "app/data_directory.h"

#include <cstdlib>
#include <filesystem>

namespace npr {
namespace fs = std::filesystem;
namespace {

bool holdsData(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "palettes" / "crosshatch" / "crosshatch.palette", ec);
}

}  // namespace

std::vector<std::string> dataDirectoryCandidates() {
  std::vector<std::string> out;
  if (const char* env = std::getenv("NPR_DATA_DIR"); env && *env) out.emplace_back(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back((exe.parent_path().parent_path() / "share" / "npr-viewer").string());
#ifdef NPR_SOURCE_DIR
  out.emplace_back(NPR_SOURCE_DIR);
#endif
  return out;
}

std::string dataDirectory() {
  // Found once: the folders do not move while the viewer runs.
  static const std::string dir = [] {
    const std::vector<std::string> candidates = dataDirectoryCandidates();
    for (const std::string& c : candidates)
      if (holdsData(c)) return c;
    return candidates.empty() ? std::string(".") : candidates.front();
  }();
  return dir;
}

std::string defaultModelPath() { return (fs::path(dataDirectory()) / "models" / "bunny.obj").string(); }
std::string defaultPalettePath() { return (fs::path(dataDirectory()) / "palettes" / "crosshatch" / "crosshatch.palette").string(); }

}  // namespace npr
