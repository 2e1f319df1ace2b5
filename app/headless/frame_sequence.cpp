// Frame ranges and the sequence's clock (see frame_sequence.h).
#include "app/headless/frame_sequence.h"

#include <cmath>
#include <cstdio>

namespace npr {

Result<FrameRange> parseFrameRange(const std::string& spec, int frames) {
  const std::string allowed = "frames 0.." + std::to_string(frames - 1) + " of the sequence";
  int first = 0, last = 0, used = 0;
  const bool pair = std::sscanf(spec.c_str(), "%d-%d%n", &first, &last, &used) == 2 && std::size_t(used) == spec.size();
  if (!pair) {
    used = 0;
    if (std::sscanf(spec.c_str(), "%d%n", &first, &used) != 1 || std::size_t(used) != spec.size() || spec.empty() || spec[0] == '-' ||
        spec[0] == '+' || spec[0] == ' ')
      return Error{"--frame-range must be FIRST-LAST or N (frame numbers from 0, as --save-frames names them), got '" + spec + "'"};
    last = first;
  }
  if (spec[0] == '-' || spec[0] == '+' || spec[0] == ' ' || first < 0 || last < 0)
    return Error{"--frame-range must be FIRST-LAST with frame numbers from 0, got '" + spec + "'"};
  if (last < first) return Error{"--frame-range " + spec + " runs backwards: FIRST must not be after LAST"};
  if (last >= frames) return Error{"--frame-range " + spec + " is outside the " + allowed};
  return FrameRange{first, last};
}

double sequenceTime(double start, int f, double fps, double speed, double length) {
  if (!(length > 0.0)) return 0.0;
  const double t = std::fmod(start + double(f) / fps * speed, length);
  return t < 0.0 ? t + length : t;
}

glm::vec3 turntableLight(const glm::vec3& light, const glm::vec3& centre, float degrees) {
  // The orbit camera's yaw turns its eye from +z towards +x: the same turn about +y.
  const float a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
  const glm::vec3 d = light - centre;
  return centre + glm::vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

}  // namespace npr
