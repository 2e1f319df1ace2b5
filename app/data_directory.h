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
// The shipped palettes' folder names (palettes/NAME/ holding a .palette) and styles' names
// (palettes/styles/NAME.style), sorted: what a name given for either may be.
std::vector<std::string> shippedPaletteNames();
std::vector<std::string> shippedStyleNames();
// NAME when `paletteFile` is a shipped palette's (palettes/NAME/...), else the file's absolute
// path: how a saved style names it, so the style travels to another machine.
std::string paletteNameOrPath(const std::string& paletteFile);
// Empty when NPR_DATA_DIR is unset or holds the data; else why it does not.
std::string dataDirectoryProblem();

}  // namespace npr
