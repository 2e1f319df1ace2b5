// The overlay (F1 or Tab): frame time, counters, the scene's settings as widgets, load
// warnings and the key bindings. Built once per frame between ImGui's new frame and render.
#pragma once

#include "app/window/viewer.h"

namespace npr {

void drawOverlay(Viewer& viewer);

}  // namespace npr
