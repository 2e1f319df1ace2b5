// An OpenGL core context with no window: EGL on Mesa's surfaceless platform. Tests,
// benchmarks and `npr-viewer --headless` render through it into an OffscreenTarget.
#pragma once

#include <memory>
#include <string>

#include "renderer/core/result.h"

namespace npr {

class HeadlessContext {
 public:
  // Creates the context (4.5 core, falling back to 3.3 core) and makes it current on this
  // thread. `debug` requests a KHR_debug context and installs the error callback.
  static Result<std::unique_ptr<HeadlessContext>> create(bool debug = true);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string description() const;  // "4.5 (Core Profile) Mesa ... llvmpipe"

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace npr
