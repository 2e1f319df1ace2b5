// Names for files the viewer writes on its own (screenshots, line exports, styles): the next
// number after the highest already in the folder, so nothing is ever overwritten, across runs
// too (npr-screenshot-0001.png, npr-screenshot-0002.png, ...).
#pragma once

#include <filesystem>
#include <string>

namespace npr {

// DIR/STEM-NNNN.EXT with NNNN one past the highest number of such a file in DIR (0001 when
// there is none); `extension` with its dot.
std::filesystem::path nextFreeName(const std::filesystem::path& dir, const std::string& stem, const std::string& extension);

}  // namespace npr
