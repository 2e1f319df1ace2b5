// Style files: a whole look in plain `key value` lines, like the palette file. The keys are
// the settings table's (the README's settings reference lists them), plus `name TEXT`; `#` starts a comment.
// Palettes are a shipped palette's folder name or a path relative to the style file. Shipped
// styles live in palettes/styles/; `--style NAME|FILE`, `--save-style FILE`, the overlay's
// style list and its "save style" use them. A style that fails to load or apply changes
// nothing: the message names the file, the line and the reason.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/settings/look.h"
#include "app/viewer_state.h"
#include "renderer/core/result.h"

namespace npr {

struct Style {
  std::string file, name;
  std::optional<std::string> palette;  // resolved to a path
  std::vector<SettingValue> values;    // the other rows, in the file's order
};

// The shipped styles (palettes/styles/*.style), sorted.
std::vector<std::string> discoverStyles();
// The one resolver of what names a style: a style file, or NAME (palettes/styles/NAME.style).
// Else the reason, with the closest shipped names and the list of them.
[[nodiscard]] Result<std::string> findStyle(const std::string& nameOrFile);
// The one resolver of what names a palette: a .palette file or a folder holding one (relative
// to `baseDirectory`), or a shipped palette's NAME; "none" as given. Else the reason, with the
// closest shipped names and the list of them.
[[nodiscard]] Result<std::string> findPalette(const std::string& nameOrPath, const std::string& baseDirectory);
[[nodiscard]] Result<Style> loadStyle(const std::string& path);
// Applies a style: its palette first (a palette that fails leaves everything as it was), then
// the settings it names; what it does not name stays, except within the sections that reset
// together (lines, strokes: a style that names one of their settings sets them all).
[[nodiscard]] Status applyStyle(const Style& style, ViewerState& state, Renderer& renderer);
// The current look as a style file's text (what "save style" and --save-style write).
std::string styleText(const ViewerState& state, const Renderer& renderer, const std::string& name);
// Writes styleText to `file`; the error names the file.
[[nodiscard]] Status saveStyle(const ViewerState& state, const Renderer& renderer, const std::string& name, const std::string& file);

}  // namespace npr
