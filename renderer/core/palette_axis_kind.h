// What picks a two-dimensional palette's row (a palette file's `axis` line): one enum that
// the palette files, the palettes on the GPU and the program variants all read.
#pragma once

namespace npr {

enum class PaletteAxisKind { None, Depth, Facing, Detail };

}  // namespace npr
