// The palette maker (`npr-viewer --make-palette`): the original's workflow, where users built a
// palette by applying one Photoshop filter to an image again and again, as a command. A ladder
// applies its step progressively through OpenImageIO's image algorithms; `--tam` instead draws
// a tonal art map from the user's own stroke image (tonal_art_map.h). The result is a palette
// folder written all at once: into a temporary sibling first, moved into place only when every
// file is written, so a failure leaves nothing half-made.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "renderer/core/image.h"
#include "renderer/core/result.h"
#include "renderer/palette/palette.h"

namespace npr {

enum class Ladder { Blur, Offset, Solarize, Posterize, Threshold, Darken, Desaturate };
std::optional<Ladder> parseLadder(const std::string& s);
const char* ladderName(Ladder l);
// The match mode that suits a ladder's palette: order where the steps change the pattern but
// not its brightness much (blur, offset, solarize, posterize), intensity where they darken
// (darken, threshold), colours where they change the hue's saturation (desaturate).
MatchMode ladderMatchMode(Ladder l);

constexpr int kMinMakerLevels = 2;

struct MakePaletteRequest {
  std::string image;               // the source image, or the stroke image with `tam`
  std::optional<Ladder> ladder;    // exactly one of ladder and tam
  bool tam = false;
  int levels = 10;                 // kMinMakerLevels .. kMaxPaletteEntries
  std::string outDir;              // must not exist, or be an empty folder
};

// The ladder's images, entry 0 first (for order ladders the most transformed, so darker light
// gets the stronger effect, as the shipped solarize palette does). `src` is opaque RGBA8.
[[nodiscard]] Result<std::vector<ImageRGBA8>> ladderImages(const ImageRGBA8& src, Ladder ladder, int levels);

// Checks the request, builds the palette and writes it; returns the palette file's path.
// `progress` (may be empty) is told the fraction done.
[[nodiscard]] Result<std::string> makePalette(const MakePaletteRequest& request, const std::function<void(double)>& progress = {});

}  // namespace npr
