// An export from the window (Ctrl+E), run a few frames at a time between the window's frames
// so the window stays responsive, shows how far it got and can cancel: the scene as an image at
// a chosen size (beyond the GL's framebuffer limit, a poster drawn tile by tile), its lines as
// SVG, or a turntable of it as a video (MP4, WebM or GIF), from the view the window shows. What
// it writes appears under its name only when finished.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "app/video/poster.h"
#include "app/video/sequence_output.h"
#include "app/viewer_state.h"
#include "renderer/core/result.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/renderer.h"

namespace npr {

enum class ExportKind { Image, Lines, Turntable };

// By the file's extension: .mp4, .webm and .gif a turntable, .svg the lines, any other an image
// (PNG, JPEG, TIFF, EXR, ... as OpenImageIO writes them).
ExportKind exportKindOf(const std::string& path);

struct ExportRequest {
  std::string path;
  glm::ivec2 size{1280, 720};
  int frames = 120;  // a turntable's
  double fps = 30.0;
};

class ExportJob {
 public:
  // Checks the request (size, frames, path) and opens what it writes; the window's view (its
  // camera and light) is taken now, so moving the view while it runs changes nothing.
  [[nodiscard]] static Result<std::unique_ptr<ExportJob>> start(const ExportRequest& request, const ViewerState& state);
  ~ExportJob();  // unfinished: what was partly written is removed
  // Renders for about `budgetMs` (at least one frame). True once everything is written.
  [[nodiscard]] Result<bool> step(ViewerState& state, Renderer& renderer, double budgetMs);
  double fraction() const;
  std::string label() const;  // "turntable.mp4: frame 37 of 120"
  const ExportRequest& request() const { return request_; }

 private:
  ExportJob() = default;
  Status renderFrame(ViewerState& state, Renderer& renderer, int frame);
  ExportRequest request_;
  ExportKind kind_ = ExportKind::Image;
  OrbitCamera camera_{0.0f, 0.0f, 1.0f};
  glm::vec3 light_{0.0f};
  std::optional<OffscreenTarget> target_;
  std::optional<SequenceOutput> output_;
  std::unique_ptr<PosterRender> poster_;  // an image larger than the GL draws at once
  int tiles_ = 0;                         // the poster's
  int done_ = 0;
  int frames() const;  // the steps: a turntable's frames, a poster's tiles, else 1
};

}  // namespace npr
