// The window's GLFW input callbacks: orbit, pan, zoom to the cursor, light drag, key actions
// (through input_map.h) and dropped files. Dear ImGui's backend chains to them and they
// ignore input the overlay captured.
#pragma once

#include "app/window/viewer.h"

namespace npr {

// Points the window at `viewer` and installs the callbacks. Install before ImGui's backend.
void installInputCallbacks(Viewer& viewer);

}  // namespace npr
