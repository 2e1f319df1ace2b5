// Optional parts of the viewer built as modules and loaded on first use: OpenImageIO (images in
// formats other than PNG and JPEG, posters, GIFs) and FFmpeg (videos). Linked into the
// executable, their libraries cost 250 ms of dynamic linking on every start, before the first
// frame (docs/performance.md, "Start-up"); most runs never call them.
#pragma once

#include "renderer/core/result.h"

namespace npr {

// The table a module's `npr_module_table` returns, after checking that the module was built
// with this binary (same interface stamp). The file is searched in the installed layout
// (EXE/../lib/npr-viewer/) and, for binaries in the build tree, in the build's module folder.
// The result is cached: the second call costs nothing, and a module is never unloaded.
// `what` says what the module is for, in the error a user reads when it is missing.
[[nodiscard]] Result<const void*> loadModuleTable(const char* fileName, const char* what);

}  // namespace npr
