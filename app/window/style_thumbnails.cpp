// The style menu's pictures (see style_thumbnails.h).
#include "app/window/style_thumbnails.h"

#include <algorithm>
#include <filesystem>

#include "app/data_directory.h"
#include "app/settings/style_file.h"
#include "renderer/lighting/lighting_state.h"

namespace npr {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

}  // namespace

std::optional<unsigned> StyleThumbnails::texture(const std::string& style) const {
  const auto it = pictures_.find(style);
  if (it == pictures_.end()) return std::nullopt;
  return it->second.colourTexture();
}

std::optional<ImageRGBA8> StyleThumbnails::picture(const std::string& style) const {
  const auto it = pictures_.find(style);
  if (it == pictures_.end()) return std::nullopt;
  return it->second.readRGBA8();
}

std::string StyleThumbnails::sceneKey(const ViewerState& live) const {
  // The meshes shown (their addresses) and how many: not their transforms, which an animation
  // changes every frame.
  std::string key = live.scene.label();
  for (const ViewerObject& o : live.scene.objects())
    if (o.visible) key += '|' + std::to_string(reinterpret_cast<std::uintptr_t>(o.mesh.get()));
  return key;
}

Status StyleThumbnails::drawStep(const ViewerState& live) {
  if (!requested_) return okStatus();
  requested_ = false;
  const std::string key = sceneKey(live);
  if (key != key_) {
    pictures_.clear();
    failed_.clear();
    renderer_.reset();
    meshes_.clear();
    key_ = key;
    camera_ = live.view(float(kWidth) / float(kHeight));
    styles_ = discoverStyles();
  }
  const auto next = std::find_if(styles_.begin(), styles_.end(), [&](const std::string& s) { return !pictures_.count(s) && !contains(failed_, s); });
  if (next == styles_.end()) {
    renderer_.reset();  // all drawn: the second copy of the meshes goes
    meshes_.clear();
    return okStatus();
  }
  if (!renderer_) {
    Result<std::unique_ptr<Renderer>> r = Renderer::create();
    if (!r) return Error{"style pictures: " + r.error()};
    renderer_ = std::move(*r);
    // The meshes are held here too: the window may open another file while pictures are drawn.
    for (const ViewerObject& o : live.scene.objects())
      if (o.visible && o.mesh) {
        meshes_.push_back(o.mesh);
        renderer_->scene().add(*o.mesh, o.placed);
      }
  }
  const std::string file = *next;
  const Status drawn = drawStyle(file, live);
  if (!drawn) {
    failed_.push_back(file);
    return Error{"style picture of " + std::filesystem::path(file).stem().string() + ": " + drawn.error()};
  }
  return okStatus();
}

Status StyleThumbnails::drawStyle(const std::string& file, const ViewerState& live) {
  // The window's look with the style over it, as choosing it in the menu gives (what a style
  // does not name stays), lit by the window's light; the files' own lights are not used.
  ViewerState look;
  look.echo = false;
  look.settings = live.settings;
  look.light = live.light;
  look.lightFollowsCamera = live.lightFollowsCamera;
  look.fileLights = false;
  applyDefaultMaterial(renderer_->lighting());
  Result<Style> style = loadStyle(file);
  if (!style) return Error{style.error()};
  if (!style->palette) {
    const bool current = live.paletteIndex >= 0 && live.paletteIndex < static_cast<int>(live.palettes.size());
    if (Status s = look.loadPalette(current ? live.palettes[static_cast<std::size_t>(live.paletteIndex)] : defaultPalettePath(), *renderer_); !s)
      return s;
    look.settings = live.settings;  // the palette's defaults are the window's already
  }
  if (Status s = applyStyle(*style, look, *renderer_); !s) return s;
  Result<OffscreenTarget> target = OffscreenTarget::create(kWidth, kHeight);
  if (!target) return Error{target.error()};
  target->bind();
  if (Status s = look.applyLight(*renderer_, *camera_); !s) return s;
  if (Status s = renderer_->render(*camera_, look.settings, {0, 0, kWidth, kHeight}); !s) return s;
  pictures_.emplace(file, std::move(*target));
  return okStatus();
}

}  // namespace npr
