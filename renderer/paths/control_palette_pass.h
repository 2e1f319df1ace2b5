// Control-image palettes (seed 003, after Akleman et al. 2016): after a path has drawn the
// surface with the main palette, the occlusion palette is blended over it with alpha
// o = 1 - the occlusion factor, then the shadow palette with alpha s = the share of diffuse
// light the shadow maps block, each palette matched to the same lit colour by its own
// matcher. The result weighs the three palettes by the partition of unity of
// lighting/control_weights.h. Drawn per pixel in every palette path (the per-triangle paths'
// layers too: their parameters vary within a triangle); a palette whose parameter this frame
// lacks (no shadow maps, occlusion off or not baked) costs nothing.
#pragma once

#include "renderer/settings/choices.h"
#include "renderer/frame/frame_context.h"

namespace npr {

[[nodiscard]] Status drawControlPalettes(FrameContext& frame, RenderPath path);

}  // namespace npr
