// The painterly strokes' brushes as coverage images: the stroke pass draws its particles with
// them (brush_stroke_pass.h), and a line set with texture=brush stretches the first along its
// strokes (lines/stroke_textures.h).
#pragma once

#include <cstdint>
#include <vector>

namespace npr {

inline constexpr int kBrushLength = 64, kBrushWidth = 24, kBrushes = 4;

// The brushes side by side (kBrushLength * kBrushes texels wide, kBrushWidth tall, rows from
// the top), coverage 0..255.
std::vector<std::uint8_t> brushCoverage();

}  // namespace npr
