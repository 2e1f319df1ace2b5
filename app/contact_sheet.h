// What the contact sheets (--palette-sheet, --style-sheet) are drawn with: images in and out
// of OpenImageIO's buffers, and labels in DejaVu Sans where the font is installed.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <string>

#include "renderer/core/image.h"

namespace npr {

OIIO::ImageBuf toBuf(const ImageRGBA8& img);
ImageRGBA8 fromBuf(const OIIO::ImageBuf& buf);
// Writes `text` with its baseline at (x, y); false (and `fontMissing` set, so later labels are
// not tried) when no font is found: the sheet is then drawn without labels.
bool drawText(OIIO::ImageBuf& sheet, int x, int y, const std::string& text, int size, bool& fontMissing);

}  // namespace npr
