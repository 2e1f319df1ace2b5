// Where a sequence's frames go (headless runs, the window's export): numbered PNGs
// (--save-frames), the turntable's GIF, a video (--video: MP4, WebM or GIF). Everything is opened before the first frame is rendered,
// so a bad path or a missing codec is said at once; the GIF and the video are written under a
// partial name and renamed when finished, so an interrupted run leaves nothing half-written
// under the names asked for.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "app/video/video_encoder.h"
#include "renderer/core/image.h"
#include "renderer/core/image_io.h"
#include "renderer/core/result.h"

namespace npr {

struct SequenceTargets {
  std::string framesFolder;  // empty: no PNGs
  std::string gif;           // the turntable's GIF (empty: none)
  std::string video;         // --video (empty: none)
  int videoQuality = VideoSpec::kDefaultQuality;
  int width = 0, height = 0, frames = 1;
  double fps = 30.0;
};

class SequenceOutput {
 public:
  [[nodiscard]] static Result<SequenceOutput> open(const SequenceTargets& targets);
  SequenceOutput(SequenceOutput&&) noexcept;
  SequenceOutput& operator=(SequenceOutput&&) noexcept;
  ~SequenceOutput();  // unfinished: the partial GIF and video are removed

  // Whether any frame is written at all (else the run only renders).
  bool wantsPixels() const;
  // Frame number `frame` of the sequence (its PNG is named by it).
  [[nodiscard]] Status add(ImageRGBA8 image, int frame);
  // Finishes the GIF and the video and moves them to their names; says what was written.
  [[nodiscard]] Status finish();

 private:
  SequenceOutput() = default;
  struct Partial;  // a GIF under its partial name
  SequenceTargets targets_;
  std::unique_ptr<Partial> gif_;
  std::unique_ptr<VideoEncoder> video_;
  int written_ = 0;
};

}  // namespace npr
