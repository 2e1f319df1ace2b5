// The palette tools of the command line: --make-palette (renderer/palette/palette_maker.h) and
// --palette-sheet, a contact sheet per palette: its levels in a row with their tones, and a
// lit sphere drawn with it.
#pragma once

#include "app/cli.h"

namespace npr {

int runPaletteMaker(const Options& o);
int runPaletteSheets(const Options& o);

}  // namespace npr
