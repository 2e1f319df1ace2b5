// The window's message bar: failures the user must see (a failed open, a refused palette or
// style, a failed export) across the top of the scene, until dismissed. A file opened from a
// file manager has no terminal: this is where its error shows.
#pragma once

#include "app/window/viewer.h"

namespace npr {

// Draws ViewerState::problems, if any; call between ImGui's new frame and its end.
void drawMessageBar(Viewer& viewer);

}  // namespace npr
