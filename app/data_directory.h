// Where the shipped palettes, styles and default models are, for a build tree, an installed
// tree (PREFIX/bin/npr-viewer beside PREFIX/share/npr-viewer) or a tree moved anywhere.
#pragma once

#include <string>
#include <vector>

namespace npr {

// The first folder that holds the shipped data, of: $NPR_DATA_DIR (an explicit choice wins),
// ../share/npr-viewer beside the executable (an installed or moved tree), the source tree the
// binary was built from. When none does, the first candidate (messages then name what is missing).
std::string dataDirectory();
// Every folder dataDirectory() looks at, in order, for --version and messages.
std::vector<std::string> dataDirectoryCandidates();
std::string defaultModelPath();
std::string defaultPalettePath();

}  // namespace npr
