// The scene's clock (see animation_playback.h).
#include "app/animation_playback.h"

#include <cmath>

#include "renderer/core/printable.h"

namespace npr {

void Playback::advance(double seconds, double length) {
  if (!playing || !(seconds > 0.0) || !std::isfinite(seconds)) return;
  time += seconds * speed;
  if (!(length > 0.0)) {
    time = 0.0;
    return;
  }
  time = std::fmod(time, length);
  if (time < 0.0) time += length;
}

Result<AnimationChoice> parseAnimationChoice(const std::string& spec, const std::vector<std::string>& names) {
  if (spec == "all" || spec.empty()) return AnimationChoice{};
  if (spec == "none") return AnimationChoice{AnimationChoice::Which::None, 0};
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == spec) return AnimationChoice{AnimationChoice::Which::One, i};
  if (spec.size() < 9 && spec.find_first_not_of("0123456789") == std::string::npos) {
    const std::size_t n = std::stoul(spec);
    if (n >= 1 && n <= names.size()) return AnimationChoice{AnimationChoice::Which::One, n - 1};
  }
  if (names.empty()) return Error{"--animation " + printable(spec) + ": the scene has no animations"};
  std::string list;
  for (std::size_t i = 0; i < names.size() && i < 12; ++i) list += (i ? ", " : "") + names[i];
  return Error{"--animation: no animation named '" + printable(spec) + "' (the scene's: " + list + (names.size() > 12 ? ", ..." : "") +
               "; or a number from 1 to " + std::to_string(names.size()) + ", all or none)"};
}

}  // namespace npr
