// Applying settings to the viewer (see look.h).
#include "app/settings/look.h"

#include <algorithm>
#include <set>

#include "app/data_directory.h"
#include <tuple>

#include "renderer/core/printable.h"

namespace npr {

Look currentLook(const ViewerState& state, const Renderer& renderer) {
  Look l;
  l.render = state.settings;
  l.light = state.light;
  l.tone = renderer.lighting().toneModel();
  l.toneParameters = renderer.lighting().toneParameters();
  l.palette = state.palette ? state.palette->file : std::string();
  l.shadowPalette = state.shadowPalette;
  l.occlusionPalette = state.occlusionPalette;
  return l;
}

namespace {

bool sameTone(const ToneParameters& a, const ToneParameters& b) {
  return a.blue == b.blue && a.yellow == b.yellow && a.alpha == b.alpha && a.beta == b.beta && a.splashAlpha == b.splashAlpha &&
         a.splashPower == b.splashPower;
}

Status located(const SettingValue& v, const Status& s) {
  if (s) return s;
  return Error{v.where + ": " + v.row->key + " '" + printable(v.value) + "': " + s.error()};
}

}  // namespace

Status applySettings(const std::vector<SettingValue>& values, bool wholeSections, ViewerState& state, Renderer& renderer) {
  // Every value parses before anything changes.
  Look scratch = currentLook(state, renderer);
  const SettingValue* palette = nullptr;
  for (const SettingValue& v : values) {
    if (Status s = located(v, v.row->parse(v.value, scratch)); !s) return s;
    if (v.row->key == "palette") palette = &v;
  }
  // Control palettes are read before anything changes, so a broken one leaves the look as it
  // was (an upload failing after them is the rare exception).
  for (const auto& [file, current, what] : {std::tuple{&scratch.shadowPalette, &state.shadowPalette, "shadow palette"},
                                             std::tuple{&scratch.occlusionPalette, &state.occlusionPalette, "occlusion palette"}})
    if (!file->empty() && *file != *current)
      if (Result<Palette> p = loadPalette(*file); !p) return Error{std::string(what) + " not loaded: " + p.error()};
  // The palette first: it may fail, and it brings its own defaults.
  if (palette)
    if (Status s = state.loadPalette(scratch.palette, renderer); !s) return Error{palette->where + ": " + s.error()};
  Look look = currentLook(state, renderer);
  if (wholeSections) {
    std::set<std::string> named, sections;
    for (const SettingValue& v : values) named.insert(v.row->key), sections.insert(v.row->section);
    const Look defaults;
    for (const SettingSection& section : settingSections())
      if (section.resetsTogether && sections.count(section.name))
        for (const Setting& row : settingsTable())
          if (row.section == section.name && !named.count(row.key)) (void)row.parse(row.format(defaults), look);
  }
  for (const SettingValue& v : values)
    if (v.row->key != "palette") (void)v.row->parse(v.value, look);
  // Commit.
  if (look.shadowPalette != state.shadowPalette)
    if (Status s = state.setControlPalette(ControlParameter::Shadow, look.shadowPalette, renderer); !s) return s;
  if (look.occlusionPalette != state.occlusionPalette)
    if (Status s = state.setControlPalette(ControlParameter::Occlusion, look.occlusionPalette, renderer); !s) return s;
  if (look.tone != renderer.lighting().toneModel() || !sameTone(look.toneParameters, renderer.lighting().toneParameters()))
    if (Status s = renderer.lighting().setToneModel(look.tone, look.toneParameters); !s) return s;
  state.settings = look.render;
  state.light = look.light;
  return okStatus();
}

std::string lookText(const Look& look) {
  std::string out;
  for (const Setting& row : settingsTable())
    if (row.saved && !(row.key == "palette" && look.palette.empty())) {
      std::string value = row.format(look);
      // A shipped palette by its name: the saved style travels to another machine.
      if (row.type == SettingType::File && value != "none") value = paletteNameOrPath(value);
      if (row.repeated)  // one line per item
        for (std::size_t at; (at = value.find('\n')) != std::string::npos; value.erase(0, at + 1)) out += row.key + " " + value.substr(0, at) + "\n";
      out += row.key + " " + value + "\n";
    }
  return out;
}

}  // namespace npr
