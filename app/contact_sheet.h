// What the contact sheets (--palette-sheet, --style-sheet) are drawn with: a white sheet,
// images and swatches placed on it, and labels in DejaVu Sans where the font is installed
// (drawn with stb_truetype, Debian's libstb).
#pragma once

#include <string>

#include "renderer/core/image.h"

namespace npr {

ImageRGBA8 blankSheet(int width, int height);
// `image` with its top-left corner at (x, y); what falls outside the sheet is left out.
void paste(ImageRGBA8& sheet, int x, int y, const ImageRGBA8& image);
// An opaque rectangle of `rgb` (0..1, encoded).
void fillRect(ImageRGBA8& sheet, int x, int y, int width, int height, const float rgb[3]);
// Writes `text` with its baseline at (x, y), `size` pixels to the em; false (and `fontMissing`
// set, so later labels are not tried) when no font is found: the sheet is then drawn without
// labels.
bool drawText(ImageRGBA8& sheet, int x, int y, const std::string& text, int size, bool& fontMissing);

}  // namespace npr
