// The frame's hatching orientation, the same for every model: where strokes take their
// direction from (--orient), in how many steps, and the light a light-driven orientation
// follows. Set once per frame into the pattern placement that every palette reads.
#pragma once

#include "renderer/lighting/lighting_state.h"
#include "renderer/patterns/pattern_placement.h"
#include "renderer/settings/render_settings.h"

namespace npr {

// `orient`'s source and bins (clamped) and the first enabled light's position (+z in eye space
// when none is on) into `pattern`.
void orientStrokes(PatternPlacement& pattern, const OrientSettings& orient, const LightingState& lighting);

}  // namespace npr
