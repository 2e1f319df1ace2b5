// `npr-viewer --headless`: renders frames through EGL into an offscreen framebuffer and
// optionally writes the last one. The same path serves scripts, CI and the tests.
#pragma once

#include "app/cli.h"

namespace npr {

int runHeadless(const Options& options);

}  // namespace npr
