// The window's file dialogs, drawn in the window with Dear ImGui: open (Ctrl+O, Ctrl+Shift+O)
// and save the look as a style (Ctrl+S). Drawn rather than native so they work the same under
// any desktop, Xvfb and xdotool included, and so a path can be typed with the field focused.
#pragma once

#include "app/window/viewer.h"

namespace npr {

// Draws whichever dialog Viewer::dialog names; call between ImGui's new frame and its end.
void drawFileDialogs(Viewer& viewer);

}  // namespace npr
