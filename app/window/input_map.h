// Keyboard bindings: GLFW key codes to viewer actions, kept apart from the window so the
// mapping is testable without one, and listed once for the help panel.
#pragma once

#include <optional>
#include <vector>

namespace npr {

enum class Action {
  Quit, ToggleOverlay, ToggleHelp,
  Screenshot,     // param: 1 the whole window with the panel (Shift+F12), 0 the scene at the window's size
  SelectPalette,  // param: palette number, 0-based
  NextPalette, PreviousPalette, CycleMatch, RangeScaleUp, RangeScaleDown, CyclePath, ToggleSplit,
  FrameModel, ResetView, ToggleLightFollow, ToggleVsync, CyclePattern, TogglePlay,
  MoveLight,      // param: axis * 2 + (positive ? 1 : 0); axis 0 = x, 1 = y, 2 = z
  Open,           // param: 1 adds to the scene (Ctrl+Shift+O), 0 replaces it (Ctrl+O)
  SaveStyle,      // Ctrl+S: the look under a typed name
  Export,         // Ctrl+E: a picture at a chosen size, the lines, a turntable video
};

struct KeyAction {
  Action action;
  int param = 0;
  bool operator==(const KeyAction& o) const { return action == o.action && param == o.param; }
};

// `key` and `mods` are GLFW's codes. Returns nothing for unbound keys.
std::optional<KeyAction> actionForKey(int key, int mods);

struct Binding {
  const char* keys;
  const char* what;
};
const std::vector<Binding>& keyBindings();

}  // namespace npr
