// Settings as data: every user setting of the look is one row of settingsTable()
// (settings_table.cpp), and the command line, style files, the overlay and the generated
// settings reference all read that table. A row holds its name, help, section, type, range
// and default, whether a style saves it, and how it is parsed and formatted; nothing else in
// the app retypes a setting's name, range or message.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/result.h"
#include "renderer/lighting/lighting_state.h"
#include "app/viewer_defaults.h"
#include "renderer/settings/render_settings.h"

namespace npr {

// Everything a style describes: the renderer's settings plus the parts of the look that live
// beside them (the light, the tone model of the lighting state, the palettes' files).
struct Look {
  RenderSettings render = viewerDefaultSettings();
  glm::vec3 light{2.0f, 2.5f, 3.0f};  // scene space (model radius 1)
  ToneModel tone = ToneModel::OpenGL;
  ToneParameters toneParameters;
  std::string palette;                          // the main palette's file (loaded first)
  std::string shadowPalette, occlusionPalette;  // control images; empty: none
};

// How a row is edited in the overlay, and what its values look like.
enum class SettingType {
  Bool,    // on|off (a flag on the command line: --key, --no-key)
  Int,     // an integer in [min, max]
  Float,   // a finite number in [min, max]
  Choice,  // one of `choices`
  Kinds,   // none, or some of `choices` separated by commas
  Colour,  // R,G,B each in 0..1
  Vector,  // X,Y,Z finite numbers
  File,    // a shipped palette's folder name, a path, or none
  Text,    // a value of its own form (see help and example)
};

struct Setting {
  std::string key;      // the command line's --key and the style file's key
  std::string label;    // the overlay's
  std::string help;
  std::string section;  // the feature it belongs to: the overlay's and reference's grouping
  SettingType type = SettingType::Text;
  double min = 0.0, max = 0.0;  // Int and Float
  bool logarithmic = false;     // Float: the overlay's slider
  std::vector<std::string> choices;  // Choice and Kinds
  std::string example;  // Text: a valid value (docs; the round-trip test)
  bool saved = true;    // written by "save style" and --save-style
  bool cli = true;      // an option of its own on the command line
  bool cliTakesValue = false;  // Bool: `--key on|off` instead of a flag
  bool applyOnRelease = false;  // the overlay applies it when the slider is let go (it recomputes a cache)
  // A list, one item per line: a style file may name the key on several lines and the command
  // line take the option several times (each adds an item); the value is the whole list, its
  // items separated by line ends, and parse replaces the list.
  bool repeated = false;
  std::vector<std::pair<std::string, std::string>> cliAliases;  // older names: {"--name", value}

  // The row's value in `look` as text its parse takes back.
  std::function<std::string(const Look&)> format;
  // Sets the row in `look` from `value`; the error says why ("must be in 0..1"), the caller
  // says where (the option, the file and line).
  std::function<Status(const std::string& value, Look& look)> parse;
  // The overlay edits typed rows in place (null for the others).
  std::function<bool*(Look&)> boolRef;
  std::function<int*(Look&)> intRef;
  std::function<float*(Look&)> floatRef;
  std::function<glm::vec3*(Look&)> vectorRef;  // Colour, Vector
  // The overlay shows the row only when this holds (null: always).
  std::function<bool(const Look&)> shown;

  // "0.125..16", "screen|anchored|object", ... (help, messages, the reference).
  std::string valueForm() const;
  // The value's placeholder in --help: on|off, N, a few choices joined by |, R,G,B, X,Y,Z, ...
  std::string typeName() const;
};

// A section: a feature's rows, in the order the overlay and the reference show them. A style
// that names any row of a section that `resetsTogether` sets the whole section: the rows it
// does not name go back to their defaults (the lines and the strokes are one look each).
struct SettingSection {
  std::string name, title;
  bool resetsTogether = false;
};

const std::vector<Setting>& settingsTable();
const std::vector<SettingSection>& settingSections();
// The row named `key` (a style file's key or an option without its dashes); null if none.
const Setting* findSetting(const std::string& key);


// `s` without leading and trailing blanks (spaces, tabs, line ends): what values and style
// lines are compared as.
std::string trimmed(const std::string& s);

}  // namespace npr
