// H: the window's keys over the scene, where they are read at a glance (not at the end of the
// scrolling panel), until H again or Esc.
#pragma once

#include "app/window/viewer.h"

namespace npr {

// Draws the key list when Viewer::help is set; call between ImGui's new frame and its end.
void drawHelpOverlay(Viewer& viewer);

}  // namespace npr
