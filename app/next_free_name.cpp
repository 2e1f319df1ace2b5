// Numbered output names (see next_free_name.h).
#include "app/next_free_name.h"

#include <cstdio>
#include <system_error>

namespace npr {
namespace fs = std::filesystem;

fs::path nextFreeName(const fs::path& dir, const std::string& stem, const std::string& extension) {
  const std::string prefix = stem + "-";
  long highest = 0;
  std::error_code ec;
  for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - extension.size(), extension.size(), extension) != 0)
      continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    highest = std::max(highest, std::stol(digits));
  }
  // Past the highest, and past any name taken meanwhile.
  for (long n = highest + 1;; ++n) {
    char number[24];
    std::snprintf(number, sizeof number, "%04ld", n);
    const fs::path candidate = dir / (prefix + number + extension);
    if (!fs::exists(candidate, ec)) return candidate;
  }
}

}  // namespace npr
