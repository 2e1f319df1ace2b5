// Recent files kept between runs (see recent_files.h).
#include "app/window/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace npr {
namespace fs = std::filesystem;
namespace {

fs::path recentFile() {
  if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return fs::path(x) / "npr-viewer" / "recent-files";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".local" / "state" / "npr-viewer" / "recent-files";
  return {};
}

// A line we wrote: a path of printable characters, of a sane length.
bool plausible(const std::string& line) {
  if (line.empty() || line.size() > 4096) return false;
  return std::none_of(line.begin(), line.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; });
}

}  // namespace

std::vector<std::string> loadRecentFiles() {
  std::vector<std::string> files;
  const fs::path p = recentFile();
  std::error_code ec;
  if (p.empty() || !fs::is_regular_file(p, ec) || fs::file_size(p, ec) > 64 * 1024) return files;
  std::ifstream in(p);
  for (std::string line; files.size() < kRecentFiles && std::getline(in, line);)
    if (plausible(line) && std::find(files.begin(), files.end(), line) == files.end()) files.push_back(line);
  return files;
}

void saveRecentFiles(const std::vector<std::string>& files) {
  const fs::path p = recentFile();
  if (p.empty()) return;
  std::error_code ec;
  fs::create_directories(p.parent_path(), ec);
  const fs::path partial = p.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::trunc);
    for (std::size_t i = 0; i < files.size() && i < kRecentFiles; ++i)
      if (plausible(files[i])) out << files[i] << '\n';
    if (!out) return;
  }
  fs::rename(partial, p, ec);  // whole or not at all: two viewers closing together keep one list
}

void addRecentFile(std::vector<std::string>& files, const std::string& path) {
  files.erase(std::remove(files.begin(), files.end(), path), files.end());
  files.insert(files.begin(), path);
  if (files.size() > kRecentFiles) files.resize(kRecentFiles);
}

}  // namespace npr
