// Small pictures of the shipped styles on the scene the window shows, for the overlay's style
// menu: a style picked by looking at the user's own model (as --style-sheet does headless).
// They are drawn by a renderer of their own, so the window's renderer keeps what it carries
// from frame to frame (the tone range's smoothing, the anchored patterns' frames, the lines'
// chains): each style applied to it and taken back would disturb them. One picture is drawn
// per window frame while the menu is open, so the menu fills in without stopping the window;
// the second renderer (a second copy of the meshes on the GPU) is let go once all are drawn.
// Every picture shows the view and the scene as they were when the menu first asked; a changed
// scene (another file, an object shown or hidden) draws them again.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer_state.h"
#include "renderer/core/result.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/renderer.h"

namespace npr {

class StyleThumbnails {
 public:
  static constexpr int kWidth = 128, kHeight = 96;
  // The picture of the style file `style` (its colour texture, bottom row first), or none yet.
  std::optional<unsigned> texture(const std::string& style) const;
  // The menu was open this frame: drawStep() draws the next picture missing.
  void request() { requested_ = true; }
  // Draws one missing picture of `live`'s scene from its view (taken, at the pictures' shape,
  // when the scene's first picture is drawn), when the menu asked since the last call; leaves
  // its own framebuffer bound (the caller binds its own after). A style that fails is left
  // without a picture, its reason returned once.
  [[nodiscard]] Status drawStep(const ViewerState& live);
  // The picture read back (for tests); none when not drawn.
  std::optional<ImageRGBA8> picture(const std::string& style) const;
  // How many of the shipped styles have their picture, and whether the second renderer is held.
  std::size_t drawn() const { return pictures_.size(); }
  bool holdsRenderer() const { return renderer_ != nullptr; }

 private:
  std::string sceneKey(const ViewerState& live) const;
  [[nodiscard]] Status drawStyle(const std::string& file, const ViewerState& live);
  bool requested_ = false;
  std::string key_;  // the scene the pictures show
  std::optional<CameraMatrices> camera_;
  std::vector<std::string> styles_, failed_;
  std::unique_ptr<Renderer> renderer_;
  std::vector<std::shared_ptr<const Mesh>> meshes_;  // what renderer_'s scene points at
  std::map<std::string, OffscreenTarget> pictures_;
};

}  // namespace npr
