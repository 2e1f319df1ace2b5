// The scene's clock: which of its files' animations play (all of them, none, or one), the
// scene time they are posed at, and whether and how fast it runs. One clock for the whole
// scene: every playing animation is sampled at the same time, and the clock loops over the
// longest of them (a shorter one holds its last pose until the loop).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "renderer/core/result.h"

namespace npr {

struct AnimationChoice {
  enum class Which { All, None, One };
  Which which = Which::All;
  std::size_t one = 0;  // Which::One: into SceneObjects::animations()
  bool operator==(const AnimationChoice& o) const { return which == o.which && (which != Which::One || one == o.one); }
};

struct Playback {
  AnimationChoice choice;
  double time = 0.0;     // seconds of scene time
  bool playing = false;
  double speed = 1.0;    // scene seconds per real second
  // Runs the clock by `seconds` of real time when playing, looping over [0, length].
  void advance(double seconds, double length);
};

// --animation: "all", "none", a name, or a number from 1 as --info lists them (`names`, in
// scene order). The message names the choices when nothing matches.
Result<AnimationChoice> parseAnimationChoice(const std::string& spec, const std::vector<std::string>& names);

}  // namespace npr
