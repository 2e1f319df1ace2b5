// Builds the first scene from the command line: model, palettes, overrides. Shared by the
// window, --headless and --benchmark.
#pragma once

#include "app/cli.h"
#include "app/viewer_state.h"

namespace npr {

// Loads what the options name (or the defaults). A model or palette that fails to load is
// an error here: there is nothing yet to fall back to.
Status startScene(const Options& options, ViewerState& state, Renderer& renderer);

}  // namespace npr
