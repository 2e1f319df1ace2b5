// Applying settings to the viewer: the look the viewer shows now, and how rows from a style
// file or the command line change it. One way for both, all or nothing: every value is
// checked and every palette loaded before anything changes, and a failure names the option or
// the file and line.
#pragma once

#include <string>
#include <vector>

#include "app/settings/setting.h"
#include "app/viewer_state.h"

namespace npr {

// One row's value as given, and where it was given ("--pattern-scale", "a.style line 3").
struct SettingValue {
  const Setting* row = nullptr;
  std::string value;
  std::string where;
};

// The look the viewer shows now.
Look currentLook(const ViewerState& state, const Renderer& renderer);
// Sets `values` over the current look, in order. With `wholeSections` (styles), naming a row
// of a section that resets together returns that section's other rows to their defaults. A
// `palette` row is loaded first and brings its own defaults, which the other rows override.
[[nodiscard]] Status applySettings(const std::vector<SettingValue>& values, bool wholeSections, ViewerState& state, Renderer& renderer);
// The look's saved rows as `key value` lines.
std::string lookText(const Look& look);

}  // namespace npr
