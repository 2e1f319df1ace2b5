// Key-to-action table (see input_map.h).
#include "app/window/input_map.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace npr {

std::optional<KeyAction> actionForKey(int key, int mods) {
  if (mods & GLFW_MOD_CONTROL) {
    // Ctrl chords are the file commands only (Ctrl+S must not move the light as S does).
    if (key == GLFW_KEY_O) return KeyAction{Action::Open, (mods & GLFW_MOD_SHIFT) ? 1 : 0};
    if (key == GLFW_KEY_S) return KeyAction{Action::SaveStyle};
    if (key == GLFW_KEY_E) return KeyAction{Action::Export};
    return std::nullopt;
  }
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) return KeyAction{Action::SelectPalette, key - GLFW_KEY_1};
  switch (key) {
    case GLFW_KEY_ESCAPE: return KeyAction{Action::Quit};
    case GLFW_KEY_F1:
    case GLFW_KEY_TAB: return KeyAction{Action::ToggleOverlay};
    case GLFW_KEY_H: return KeyAction{Action::ToggleHelp};
    case GLFW_KEY_F12: return KeyAction{Action::Screenshot, (mods & GLFW_MOD_SHIFT) ? 1 : 0};
    case GLFW_KEY_RIGHT_BRACKET: return KeyAction{Action::NextPalette};
    case GLFW_KEY_LEFT_BRACKET: return KeyAction{Action::PreviousPalette};
    case GLFW_KEY_M: return KeyAction{Action::CycleMatch};
    case GLFW_KEY_EQUAL:  // '+' is shift+'=' on most layouts
    case GLFW_KEY_KP_ADD: return KeyAction{Action::RangeScaleUp};
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: return KeyAction{Action::RangeScaleDown};
    case GLFW_KEY_P: return KeyAction{Action::CyclePath};
    case GLFW_KEY_B: return KeyAction{Action::ToggleSplit};
    case GLFW_KEY_F: return KeyAction{Action::FrameModel};
    case GLFW_KEY_R: return KeyAction{Action::ResetView};
    case GLFW_KEY_L: return KeyAction{Action::ToggleLightFollow};
    case GLFW_KEY_V: return KeyAction{Action::ToggleVsync};
    case GLFW_KEY_T: return KeyAction{Action::CyclePattern};
    case GLFW_KEY_SPACE: return KeyAction{Action::TogglePlay};
    case GLFW_KEY_A: return KeyAction{Action::MoveLight, 0};
    case GLFW_KEY_D: return KeyAction{Action::MoveLight, 1};
    case GLFW_KEY_S: return KeyAction{Action::MoveLight, 2};
    case GLFW_KEY_W: return KeyAction{Action::MoveLight, 3};
    case GLFW_KEY_Q: return KeyAction{Action::MoveLight, 4};
    case GLFW_KEY_E: return KeyAction{Action::MoveLight, 5};
    default: return std::nullopt;
  }
}

const std::vector<Binding>& keyBindings() {
  static const std::vector<Binding> b = {
      {"Left drag", "orbit"},
      {"Right / middle drag", "pan"},
      {"Scroll", "zoom toward the cursor"},
      {"Ctrl + left drag", "move the light in the view plane"},
      {"W A S D / Q E", "move the light in y, x / z"},
      {"L", "light follows the camera / stays in the scene"},
      {"1-9, [ ]", "choose palette / previous, next"},
      {"M", "cycle match mode"},
      {"+ / -", "IntensityRangeScale up / down"},
      {"P", "cycle render path"},
      {"B", "split view: reference beside the chosen path"},
      {"T", "pattern space: screen / anchored to the object"},
      {"F / R", "frame the scene / reset the view"},
      {"V", "vsync on/off"},
      {"Space", "play / pause the scene's animations"},
      {"F1 or Tab", "overlay"},
      {"H", "these keys, over the scene"},
      {"Ctrl+O / Ctrl+Shift+O", "open a model, scene, palette or style (type its path, Enter) / add a model to the scene"},
      {"Ctrl+S", "save the look as a style file (a name is asked; an existing file is replaced only when confirmed)"},
      {"Ctrl+E", "export: a picture at a chosen size (.png; a poster in tiles beyond the GL's limit), the lines (.svg) or a turntable (.mp4 .webm .gif), with progress; Esc cancels"},
      {"F12 / Shift+F12", "screenshot of the scene at the window's size / of the whole window (npr-screenshot-NNNN.png, never overwriting)"},
      {"Drop a file", "as Ctrl+O: a model (.obj .gltf .glb .ply .off .stl .om), palette (.palette) or style (.style); with Shift, add the model to the scene"},
      {"Double-click", "frame the object under the cursor (F: the whole scene)"},
      {"Esc", "quit"},
  };
  return b;
}

}  // namespace npr
