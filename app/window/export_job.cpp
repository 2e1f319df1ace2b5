// The window's exports, a few frames at a time (see export_job.h).
#include "app/window/export_job.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "app/headless/frame_sequence.h"
#include "app/line_export.h"
#include "app/video/video_encoder.h"
#include "renderer/core/elapsed.h"
#include "renderer/core/image_io.h"

namespace npr {
namespace {

// The partial file moved to its name once written.
Status moveIntoPlace(const std::string& partial, const std::string& path) {
  std::error_code ec;
  std::filesystem::rename(partial, path, ec);
  if (ec) return Error{"cannot rename '" + partial + "' to '" + path + "' (" + ec.message() + ")"};
  return okStatus();
}

}  // namespace

ExportKind exportKindOf(const std::string& path) {
  if (videoFormatOf(path)) return ExportKind::Turntable;
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".svg" ? ExportKind::Lines : ExportKind::Image;
}

ExportJob::~ExportJob() {
  output_.reset();  // an unfinished video or GIF removes its partial file
  poster_.reset();  // closed before its partial file goes
  if (kind_ != ExportKind::Turntable && done_ < frames() && !request_.path.empty()) {
    std::error_code ec;
    std::filesystem::remove(partialFileName(request_.path), ec);
  }
}

Result<std::unique_ptr<ExportJob>> ExportJob::start(const ExportRequest& r, const ViewerState& state) {
  std::unique_ptr<ExportJob> job(new ExportJob());
  job->request_ = r;
  job->kind_ = exportKindOf(r.path);
  // An image beyond the GL's limit is a poster, drawn in tiles (as headless --size draws it).
  const int limit = job->kind_ == ExportKind::Image ? kMaxPosterSide : maxFramebufferSide();
  if (r.size.x < 16 || r.size.y < 16 || r.size.x > limit || r.size.y > limit)
    return Error{"the size must be 16 to " + std::to_string(limit) + " pixels a side" +
                 (job->kind_ == ExportKind::Image ? "" : " (pictures may be larger: drawn in tiles)")};
  if (std::filesystem::path(r.path).filename().empty()) return Error{"no file name given"};
  const std::filesystem::path folder = std::filesystem::path(r.path).parent_path();
  std::error_code ec;
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec)) return Error{"the folder '" + folder.string() + "' does not exist"};
  job->camera_ = state.camera;
  job->light_ = state.light;
  if (job->kind_ == ExportKind::Lines) return job;  // drawn by exportSvg, which makes its own targets
  if (job->kind_ == ExportKind::Image && (r.size.x > maxFramebufferSide() || r.size.y > maxFramebufferSide())) {
    Result<std::unique_ptr<PosterRender>> poster = PosterRender::start(partialFileName(r.path), r.size, 0);
    if (!poster) return Error{poster.error()};
    job->poster_ = std::move(*poster);
    job->tiles_ = job->poster_->tiles();
    return job;
  }
  Result<OffscreenTarget> target = OffscreenTarget::create(r.size.x, r.size.y);
  if (!target) return Error{target.error()};
  job->target_ = std::move(*target);
  if (job->kind_ == ExportKind::Turntable) {
    if (r.frames < 2 || r.frames > 3600) return Error{"a turntable has 2 to 3600 frames, not " + std::to_string(r.frames)};
    SequenceTargets t;
    t.video = r.path;
    t.width = r.size.x;
    t.height = r.size.y;
    t.frames = r.frames;
    t.fps = r.fps;
    Result<SequenceOutput> out = SequenceOutput::open(t);
    if (!out) return Error{out.error()};
    job->output_ = std::move(*out);
  }
  return job;
}

Status ExportJob::renderFrame(ViewerState& state, Renderer& renderer, int frame) {
  // The window's view, turned by the frame's share of the orbit for a turntable (the light
  // with it, as headless turntables turn it); the window's own view is put back after.
  const OrbitCamera windowCamera = state.camera;
  const glm::vec3 windowLight = state.light;
  state.camera = camera_;
  if (kind_ == ExportKind::Turntable) {
    const float degrees = 360.0f * float(frame) / float(request_.frames);
    state.camera.orbit(degrees, 0.0f);
    if (!state.lightFollowsCamera) state.light = turntableLight(light_, camera_.target(), degrees);
  }
  const CameraMatrices cam = state.view(float(request_.size.x) / float(request_.size.y));
  Status st = state.applyLight(renderer, cam);
  const std::string partial = partialFileName(request_.path);
  if (st && kind_ == ExportKind::Lines) {
    st = exportSvg(renderer, cam, state.settings, request_.size, SvgContents{nullptr, false, state.palette.get()}, partial);
    if (st) st = moveIntoPlace(partial, request_.path);
  } else if (st && poster_) {
    st = poster_->drawTile(state, renderer, frame);
    if (st && frame + 1 == poster_->tiles()) {
      poster_.reset();  // finished and closed
      st = moveIntoPlace(partial, request_.path);
    }
  } else if (st) {
    target_->bind();
    st = renderer.render(cam, state.settings, {0, 0, request_.size.x, request_.size.y});
    if (st && kind_ == ExportKind::Turntable) st = output_->add(target_->readRGBA8(), frame);
    if (st && kind_ == ExportKind::Image) {
      st = writeImage(partial, target_->readRGBA8());
      if (st) st = moveIntoPlace(partial, request_.path);
    }
  }
  state.camera = windowCamera;
  state.light = windowLight;
  bindWindowFramebuffer();
  return st;
}

int ExportJob::frames() const {
  if (kind_ == ExportKind::Turntable) return request_.frames;
  return std::max(1, tiles_);
}

Result<bool> ExportJob::step(ViewerState& state, Renderer& renderer, double budgetMs) {
  const int frames = this->frames();
  const auto t0 = std::chrono::steady_clock::now();
  do {
    if (Status st = renderFrame(state, renderer, done_); !st) return Error{st.error()};
    ++done_;
  } while (done_ < frames && msSince(t0) < budgetMs);
  if (done_ < frames) return false;
  if (output_) {
    if (Status st = output_->finish(); !st) return Error{st.error()};
    output_.reset();
  }
  return true;
}

double ExportJob::fraction() const { return double(done_) / double(frames()); }

std::string ExportJob::label() const {
  const std::string name = std::filesystem::path(request_.path).filename().string();
  if (kind_ == ExportKind::Turntable)
    return name + ": frame " + std::to_string(std::min(done_ + 1, request_.frames)) + " of " + std::to_string(request_.frames);
  if (tiles_ > 1) return name + ": tile " + std::to_string(std::min(done_ + 1, tiles_)) + " of " + std::to_string(tiles_);
  return name;
}

}  // namespace npr
