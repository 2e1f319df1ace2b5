// Answers to a mistyped name: the closest of the names that exist (by edit distance), so
// `--style pencl` says "did you mean pencil?" instead of "no such file".
#pragma once

#include <string>
#include <vector>

namespace npr {

// Up to `count` of `names` within a few edits of `typed` (about a third of its length), the
// closest first.
std::vector<std::string> closestNames(const std::string& typed, const std::vector<std::string>& names, std::size_t count = 3);
// " (did you mean a or b?)", or "" when nothing is close.
std::string didYouMean(const std::string& typed, const std::vector<std::string>& names);

}  // namespace npr
