// The windowed viewer: a GLFW window, mouse and keyboard controls, drag-and-drop loading,
// and the Dear ImGui overlay. main() hands over here unless --headless/--info/... was given.
#pragma once

#include "app/cli.h"

namespace npr {

int runWindowViewer(const Options& options);

}  // namespace npr
