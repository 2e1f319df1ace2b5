// Finding the shipped data (see data_directory.h).
#include "app/data_directory.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>
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

std::vector<std::string> shippedPaletteNames() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& d : fs::directory_iterator(fs::path(dataDirectory()) / "palettes", ec)) {
    if (!d.is_directory(ec)) continue;
    for (const auto& f : fs::directory_iterator(d.path(), ec))
      if (f.path().extension() == ".palette") {
        out.push_back(d.path().filename().string());
        break;
      }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> shippedStyleNames() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& f : fs::directory_iterator(fs::path(dataDirectory()) / "palettes" / "styles", ec))
    if (f.path().extension() == ".style") out.push_back(f.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string paletteNameOrPath(const std::string& paletteFile) {
  std::error_code ec;
  const fs::path file = fs::weakly_canonical(paletteFile, ec);
  const fs::path root = fs::weakly_canonical(fs::path(dataDirectory()) / "palettes", ec);
  const fs::path relative = file.lexically_relative(root);
  // palettes/NAME/NAME.palette (or any .palette directly in NAME/), or the folder palettes/NAME:
  // the name says it.
  const auto parts = std::distance(relative.begin(), relative.end());
  if (!relative.empty() && *relative.begin() != ".." && *relative.begin() != "styles" &&
      (parts == 2 || (parts == 1 && fs::is_directory(file, ec))))
    return relative.begin()->string();
  return fs::absolute(paletteFile, ec).lexically_normal().string();
}

std::string dataDirectoryProblem() {
  const char* env = std::getenv("NPR_DATA_DIR");
  if (!env || !*env || holdsData(env)) return "";
  std::error_code ec;
  return std::string("NPR_DATA_DIR names '") + env + "', " +
         (fs::is_directory(env, ec) ? "which holds no palettes/crosshatch/crosshatch.palette" : "which is not a folder") +
         ": point it at a folder holding the viewer's palettes/ and models/, or unset it";
}

std::string defaultModelPath() { return (fs::path(dataDirectory()) / "models" / "bunny.obj").string(); }
std::string defaultPalettePath() { return (fs::path(dataDirectory()) / "palettes" / "crosshatch" / "crosshatch.palette").string(); }

}  // namespace npr
