// The per-triangle paths' scene preparation: a scene's models lit on the CPU side by side
// before the frame draws them (see the .cpp for when, and the figures).
#pragma once

#include "renderer/frame/frame_view.h"

namespace npr {

void lightTrianglesAhead(FrameView& frame);

}  // namespace npr
