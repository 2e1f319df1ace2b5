// The manual page (npr-viewer.1), generated from the command line's options, which the
// settings table generates in turn: `npr-viewer --man-page` prints it, the build installs it.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace npr {

std::string manPage(const CLI::App& app);

}  // namespace npr
