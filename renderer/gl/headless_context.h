// An OpenGL core context with no window, through EGL: on the best EGL device (a GPU before a
// software rasterizer, or the one --gpu names), else on Mesa's surfaceless platform. Tests,
// benchmarks and `npr-viewer --headless` render through it into an OffscreenTarget.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "renderer/core/result.h"
#include "renderer/gl/gl_info.h"
#include "renderer/gl/gpu_choice.h"

namespace npr {

class HeadlessContext {
 public:
  // Creates the context (4.5 core, falling back to 3.3 core) on the device `gpu` asks for and
  // makes it current on this thread. `debug` requests a KHR_debug context and installs the
  // error callback. An explicit device that fails is an error, never a silent fallback.
  static Result<std::unique_ptr<HeadlessContext>> create(bool debug = true, const GpuRequest& gpu = {});
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string description() const;  // "4.5 (Core Profile) Mesa ... / llvmpipe ..."
  const GlInfo& info() const { return info_; }

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  GlInfo info_;
};

// The request the environment variable NPR_GPU makes ("auto" when unset); for programs that
// have no --gpu option (the benchmarks, the GL tests).
[[nodiscard]] Result<GpuRequest> gpuRequestFromEnvironment();

}  // namespace npr
