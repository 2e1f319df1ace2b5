// The frame's hatching orientation (see stroke_orientation.h).
#include "renderer/orientation/stroke_orientation.h"

#include <algorithm>

namespace npr {

void orientStrokes(PatternPlacement& pattern, const OrientSettings& orient, const LightingState& lighting) {
  glm::vec4 light(0, 0, 1, 0);
  for (int i = 0; i < kMaxLights; ++i)
    if (lighting.light(i).enabled) {
      light = lighting.light(i).position;
      break;
    }
  pattern.orient = orient;
  pattern.orient.bins = std::clamp(orient.bins, OrientSettings::kMinBins, OrientSettings::kMaxBins);
  pattern.light = light;
}

}  // namespace npr
