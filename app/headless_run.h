// `npr-viewer --headless`: renders frames through EGL into an offscreen framebuffer and
// optionally writes the last one. The same path serves scripts, CI and the tests.
#pragma once

#include <memory>
#include <string>

#include "app/cli.h"
#include "renderer/gl/headless_context.h"
#include "renderer/renderer.h"

namespace npr {

int runHeadless(const Options& options);

// A windowless context with a renderer on it: what --headless and --benchmark start from.
// `debug` asks for KHR_debug error reporting (the benchmark leaves it off: it slows drawing).
struct HeadlessSession {
  std::unique_ptr<HeadlessContext> context;
  std::unique_ptr<Renderer> renderer;
};
Result<HeadlessSession> openHeadlessSession(bool debug);

// Prints "npr-viewer: MESSAGE" on stderr and returns exit status 1 (a failed load or render).
int reportFailure(const std::string& message);

}  // namespace npr
