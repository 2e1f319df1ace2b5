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

#include "app/headless/headless_session.h"
#include "app/headless/poster.h"
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
  const float aspect = float(o.size.x) / float(o.size.y);
  // A sequence of an animated scene moves it: the clock steps 1/fps scene seconds per frame.
  const bool moving = frames > 1 && state.animationLength() > 0.0;
  if (moving) state.playback.playing = true;
  const int gifFps = moving ? static_cast<int>(std::lround(o.fps)) : 30;
  std::vector<double> ms;
  // A turntable also goes into an animated GIF, frame by frame (30 frames a second, looping).
  std::optional<AnimationWriter> gif;
  const std::string gifPath = o.turntable ? (std::filesystem::path(o.saveFrames) / "turntable.gif").string() : std::string();
  if (o.turntable) {
    Result<AnimationWriter> w = AnimationWriter::open(gifPath, o.size.x, o.size.y, frames, gifFps);
    if (!w) return reportFailure(w.error());
    gif = std::move(*w);
  }
  ProgressLine progress("rendering " + std::to_string(frames) + " frames");
  std::unique_ptr<ProgressLine> bakeProgress;
  renderer->setProgress([&](const std::string& what, double f) {
    if (!bakeProgress) bakeProgress = std::make_unique<ProgressLine>(what);
    bakeProgress->update(f);
  });
  target->bind();
  CameraMatrices lastCamera = state.view(aspect);
  for (int f = 0; f < frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    state.poseScene(*renderer);
    const CameraMatrices cam = state.view(aspect);
    lastCamera = cam;
    if (Status s = state.applyLight(*renderer, cam); !s) return reportFailure("light: " + s.error());
    target->bind();
    if (Status s = renderer->render(cam, state.settings, {0, 0, o.size.x, o.size.y}); !s)
      return reportFailure("render failed: " + s.error());
    finishGpuWork();
    ms.push_back(msSince(t0));
    if (!o.saveFrames.empty() || gif) {
      const ImageRGBA8 image = target->readRGBA8();
      if (Status s = writeImage(frameFileName(o.saveFrames, f), image); !s) return reportFailure(s.error());
      if (gif)
        if (Status s = gif->append(image); !s) return reportFailure(s.error());
    }
    if (frames > 1) progress.update(double(f + 1) / frames);
    stepCameraAnimation(state.camera, o.animation, o.size);
    if (moving) state.playback.advance(1.0 / o.fps, state.animationLength());
  }
  if (!o.saveFrames.empty()) tellUser(std::to_string(frames) + " frame(s) written to " + o.saveFrames);
  if (gif) tellUser("turntable written to " + gifPath);
  std::sort(ms.begin(), ms.end());
  std::fprintf(stderr, "npr-viewer: %d frame(s) of %s at %dx%d, path %s, match %s: median %.2f ms\n", frames,
               state.scene.label().c_str(), o.size.x, o.size.y, renderPathName(state.settings.path),
               choiceName(state.settings.match), ms[ms.size() / 2]);
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
