// Headless rendering (see headless_run.h).
#include "app/headless/headless_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "app/headless/frame_sequence.h"
#include "app/headless/headless_session.h"
#include "app/headless/interrupt_guard.h"
#include "app/headless/resident_memory.h"
#include "app/video/sequence_output.h"
#include "app/video/poster.h"
#include "app/line_export.h"
#include "app/progress_line.h"
#include "app/startup.h"
#include "renderer/core/elapsed.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/core/image_io.h"
#include "renderer/gl/offscreen_target.h"
#include "app/cli.h"
#include "renderer/settings/choice_names.h"

namespace npr {

int runHeadless(const Options& o) {
  auto session = openHeadlessSession(true, o.gpu);
  if (!session) return reportFailure(session.error());
  Renderer* renderer = session->renderer.get();
  ViewerState state;
  if (Status s = startScene(o, state, *renderer); !s) return reportFailure(s.error());
  // A still beyond what the GL draws at once, or asked for in tiles: a poster.
  const bool tiled = o.tile > 0 || std::max(o.size.x, o.size.y) > maxFramebufferSide();
  if (tiled) {
    if (o.frames > 1 || !o.saveFrames.empty() || o.turntable || !o.svg.empty())
      return reportFailure("a tiled poster (--tile, or --size beyond " + std::to_string(maxFramebufferSide()) +
                           ") is one still: leave out --frames, --save-frames, --turntable and --svg");
    return renderPoster(o, state, *renderer);
  }
  auto target = OffscreenTarget::create(o.size.x, o.size.y);
  if (!target) return reportFailure(target.error());
  const int frames = std::max(1, o.frames);
  const FrameRange range = o.frameRange.value_or(FrameRange{0, frames - 1});
  const float aspect = float(o.size.x) / float(o.size.y);
  const glm::ivec4 viewport{0, 0, o.size.x, o.size.y};
  // A sequence of an animated scene moves it: the clock steps 1/fps scene seconds per frame.
  const bool moving = frames > 1 && state.animationLength() > 0.0;
  const double startTime = state.playback.time;
  const glm::vec3 startLight = state.light;
  const glm::vec3 orbitCentre = state.camera.target();
  // The outputs, opened before the first frame: a bad path or a missing codec is said now. A
  // turntable's GIF is the whole orbit's: a range of it (a farm's share) writes frames only.
  SequenceTargets targets;
  targets.framesFolder = o.saveFrames;
  if (o.turntable && o.video.empty() && !o.frameRange) targets.gif = (std::filesystem::path(o.saveFrames) / "turntable.gif").string();
  targets.video = o.video;
  targets.videoQuality = o.videoQuality;
  targets.width = o.size.x;
  targets.height = o.size.y;
  targets.frames = range.count();
  targets.fps = moving || !o.video.empty() ? o.fps : 30.0;
  const InterruptGuard interrupt;  // from here a signal stops the run between frames, cleaning up
  Result<SequenceOutput> output = SequenceOutput::open(targets);
  if (!output) return reportFailure(output.error());
  std::vector<double> ms;
  ResidentMemory memory(range.count());
  ProgressLine progress("rendering " + std::to_string(range.count()) + " frames");
  std::unique_ptr<ProgressLine> bakeProgress;
  renderer->setProgress([&](const std::string& what, double f) {
    if (!bakeProgress) bakeProgress = std::make_unique<ProgressLine>(what);
    bakeProgress->update(f);
  });
  target->bind();
  CameraMatrices lastCamera = state.view(aspect);
  const auto runStart = std::chrono::steady_clock::now();
  for (int f = 0; f <= range.last; ++f) {
    if (interrupt.raised()) {
      // Exit 128 + SIGINT, as a shell reports a run stopped by Ctrl+C.
      std::string what = "interrupted at frame " + std::to_string(f);
      if (!targets.video.empty() || !targets.gif.empty()) what += ": " + (targets.video.empty() ? targets.gif : targets.video) + " was not written";
      if (!o.saveFrames.empty() && f > range.first)
        what += "; frames " + std::to_string(range.first) + " to " + std::to_string(f - 1) + " are in " + o.saveFrames;
      tellUser(what);
      return 130;
    }
    const auto t0 = std::chrono::steady_clock::now();
    if (moving) state.playback.time = sequenceTime(startTime, f, o.fps, state.playback.speed, state.animationLength());
    state.poseScene(*renderer);
    const CameraMatrices cam = state.view(aspect);
    if (f < range.first) {
      // Before the range: only what the next frame needs from this one (frame_sequence.h).
      if (Status s = renderer->follow(cam, state.settings, viewport); !s) return reportFailure("render failed: " + s.error());
      stepCameraAnimation(state.camera, o.animation, o.size);
      continue;
    }
    lastCamera = cam;
    if (o.turntable && !state.lightFollowsCamera) state.light = turntableLight(startLight, orbitCentre, float(f) * o.animation.orbitDegrees);
    if (Status s = state.applyLight(*renderer, cam); !s) return reportFailure("light: " + s.error());
    target->bind();
    if (Status s = renderer->render(cam, state.settings, viewport); !s) return reportFailure("render failed: " + s.error());
    finishGpuWork();
    ms.push_back(msSince(t0));
    if (output->wantsPixels())
      if (Status s = output->add(target->readRGBA8(), f); !s) return reportFailure(s.error());
    memory.sample(f - range.first + 1);
    if (range.count() > 1) progress.update(double(f - range.first + 1) / range.count());
    stepCameraAnimation(state.camera, o.animation, o.size);
  }
  if (Status s = output->finish(); !s) return reportFailure(s.error());
  const double runSeconds = msSince(runStart) / 1000.0;
  std::sort(ms.begin(), ms.end());
  std::fprintf(stderr, "npr-viewer: %d frame(s) of %s at %dx%d, path %s, match %s: median %.2f ms\n", range.count(),
               state.scene.label().c_str(), o.size.x, o.size.y, renderPathName(state.settings.path),
               choiceName(state.settings.match), ms[ms.size() / 2]);
  if (range.count() > 1) {
    // Against the frame alone (what the window draws a second at this size): what reading the
    // frames back, writing and encoding them cost on top.
    const double median = ms[ms.size() / 2];
    std::fprintf(stderr, "npr-viewer: %.1f frames a second written (%.2f s in all), %.1f a second drawn alone (the median frame)%s\n",
                 range.count() / std::max(runSeconds, 1e-9), runSeconds, 1000.0 / std::max(median, 1e-6), memory.summary().c_str());
  }
  if (!o.svg.empty()) {
    const ImageRGBA8 frame = o.svgRaster ? target->readRGBA8() : ImageRGBA8{};
    const SvgContents what{o.svgRaster ? &frame : nullptr, o.svgFill, state.palette.get()};
    if (Status s = exportSvg(*renderer, lastCamera, state.settings, o.size, what, o.svg); !s) return reportFailure(s.error());
    target->bind();
  }
  if (!o.screenshot.empty()) {
    if (Status s = writeImage(o.screenshot, target->readRGBA8()); !s) return reportFailure(s.error());
  }
  if (const int errors = gl::checkErrors("end of headless run"))
    return reportFailure(std::to_string(errors) + " OpenGL error(s) during the run");
  return 0;
}

}  // namespace npr
