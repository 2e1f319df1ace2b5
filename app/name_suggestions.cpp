// Name suggestions (see name_suggestions.h).
#include "app/name_suggestions.h"

#include <algorithm>
#include <cctype>

namespace npr {
namespace {

// Levenshtein distance, case-insensitive; names are short.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::vector<std::string> closestNames(const std::string& typed, const std::vector<std::string>& names, std::size_t count) {
  if (typed.size() > 64) return {};
  const std::size_t limit = std::max<std::size_t>(2, typed.size() / 3);
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const std::string& n : names) {
    // A name that starts with what was typed is close whatever its length (`cross` for crosshatch).
    const bool prefix = typed.size() >= 3 && n.size() > typed.size() && editDistance(typed, n.substr(0, typed.size())) == 0;
    const std::size_t d = prefix ? 1 : editDistance(typed, n);
    if (d <= limit) scored.emplace_back(d, n);
  }
  std::sort(scored.begin(), scored.end());
  std::vector<std::string> out;
  for (const auto& [d, n] : scored)
    if (out.size() < count) out.push_back(n);
  return out;
}

std::string didYouMean(const std::string& typed, const std::vector<std::string>& names) {
  const std::vector<std::string> close = closestNames(typed, names);
  if (close.empty()) return "";
  std::string out = " (did you mean ";
  for (std::size_t i = 0; i < close.size(); ++i) out += (i ? (i + 1 == close.size() ? " or " : ", ") : "") + close[i];
  return out + "?)";
}

}  // namespace npr
