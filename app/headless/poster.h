// Posters: a still larger than the GL framebuffer limit (or --tile N) rendered in tiles, each a
// sub-frustum of the whole frame with its pixels offset so palette patterns continue across
// the seams, drawn with a gutter that is cut off (image-space edges read neighbours), and
// written strip by strip so the whole image is never in memory.
#pragma once

#include "app/cli.h"
#include "app/viewer_state.h"
#include "renderer/renderer.h"

namespace npr {

// Renders `state`'s scene at o.size in tiles of o.tile (or the largest the GL allows) into
// o.screenshot. Returns the exit status.
int renderPoster(const Options& o, ViewerState& state, Renderer& renderer);

}  // namespace npr
