// A windowless context with a renderer on it: what --headless, --benchmark, --gl-info and the
// palette sheets start from.
#pragma once

#include <memory>

#include "renderer/core/result.h"
#include "renderer/gl/gpu_choice.h"
#include "renderer/gl/headless_context.h"
#include "renderer/renderer.h"

namespace npr {

// Members in this order so the renderer's GL objects go before their context.
struct HeadlessSession {
  std::unique_ptr<HeadlessContext> context;
  std::unique_ptr<Renderer> renderer;
};
// `debug` asks for KHR_debug error reporting (the benchmark leaves it off: it slows drawing);
// `gpu` is --gpu's request. Warns on stderr when a software rasterizer answers although EGL
// lists a hardware device (the GPU would sit idle).
[[nodiscard]] Result<HeadlessSession> openHeadlessSession(bool debug, const GpuRequest& gpu);

}  // namespace npr
