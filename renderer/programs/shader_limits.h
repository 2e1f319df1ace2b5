// Sizes that the C++ side and the GLSL side of a program must agree on, handed to the shaders
// as #define lines by program_variants.cpp. Kept here, below the folders that own them
// (palette/palette_matcher.h's lookup tables, lines/feature_edges.h's edge kinds), so the
// variants need not include those folders.
#pragma once

namespace npr::gl {

inline constexpr int kLut1DSize = 4096;  // samples of the matcher's 1D tone over q in [0, 3]
inline constexpr int kLut3DSize = 64;    // samples per axis of the matcher's colour cube
inline constexpr int kEdgeKinds = 6;     // kinds of feature line (lines/feature_edges.h's EdgeKind)

}  // namespace npr::gl
