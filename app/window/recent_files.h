// The window's recent files, kept between runs in $XDG_STATE_HOME/npr-viewer/recent-files
// (default ~/.local/state): one path a line, newest first, ten at most. A missing or damaged
// file is an empty list; a list that cannot be written is not worth a message.
#pragma once

#include <string>
#include <vector>

namespace npr {

constexpr std::size_t kRecentFiles = 10;

std::vector<std::string> loadRecentFiles();
void saveRecentFiles(const std::vector<std::string>& files);
// `path` first in `files`, once, the list cut to kRecentFiles.
void addRecentFile(std::vector<std::string>& files, const std::string& path);

}  // namespace npr
