// --style-sheet FILE: the given scene in every shipped style, one labelled cell each, in one
// picture: a style picked by looking at the user's own model, not at the teapot.
#pragma once

#include "app/cli.h"

namespace npr {

// Returns the process's exit status (0, or 1 with the reason on stderr).
int runStyleSheet(const Options& options);

}  // namespace npr
