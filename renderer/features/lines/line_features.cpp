// The line kinds as features, drawn over the surfaces in this order: hardware outlines and the
// charcoal rim from back faces (lines/hardware_outline_pass.h), image-space edges from the
// frame's depth and normals (lines/image_edges_pass.h), each model's object-space feature
// lines (lines/line_pass.h), the scene's intersection lines (lines/intersection_lines.h), and
// the files' own points and lines.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>

#include "renderer/core/elapsed.h"
#include "renderer/core/parallel.h"
#include "renderer/features/feature.h"
#include "renderer/lines/hardware_outline_pass.h"
#include "renderer/lines/image_edges_pass.h"
#include "renderer/scene/scene_lines.h"
#include "renderer/lines/line_pass.h"
#include "renderer/lines/occlusion_layers.h"
#include "renderer/lines/stroke_textures.h"

namespace npr {
namespace {

class OutlinesFeature final : public Feature {
 public:
  const char* name() const override { return "outlines"; }
  bool active(const FrameView& f) const override { return f.settings.lines.hardware || f.settings.lines.rim; }
  Status drawOver(FrameView& f) override {
    Status result = okStatus();
    f.scene.forEach([&](Model& m) {
      if (result)
        result = drawHardwareOutlines(m.gpu(), m.placed(f.camera), f.settings.lines, f.palette, f.pattern, f.settings.match, f.viewport,
                                      f.programs, f.stats);
    });
    return result;
  }
};

class ImageEdgesFeature final : public Feature {
 public:
  const char* name() const override { return "image edges"; }
  bool active(const FrameView& f) const override { return f.settings.lines.imageSpace && !f.scene.empty(); }
  Status drawOver(FrameView& f) override {
    return pass_.draw(f.scene.placed(f.camera), f.camera, f.settings.lines, f.viewport, f.programs, f.emptyVao, f.stats);
  }

 private:
  ImageEdgesPass pass_;
};

// What a style reads from the frame: its stroke texture, loaded on first use (shared by the
// features that draw sets; a file that cannot be read is reported once, its sets then draw
// plain lines), and for colour=tone the frame's lighting and main palette.
Status prepareStyle(LineStyle& style, StrokeTextures& textures, const FrameView& f) {
  style.lighting = &f.lighting;
  style.palette = f.palette;
  style.match = f.settings.match;
  if (style.texture.empty()) return okStatus();
  Result<StrokeTexture> t = textures.find(style.texture);
  if (!t) return Error{t.error()};
  style.textureBound = *t;
  return okStatus();
}

// Whether any of `m`'s lines can show in the frame: an object wholly outside the view, by more
// than the widest line could reach in (its width grown by curvature, a sketchy stroke's
// wander), has no lines to find or draw; its chains start again when it comes back, unseen.
bool inView(const FrameView& f, const Model& m) {
  float widest = f.settings.lines.width;
  for (const LineSet& set : f.settings.lines.sets) widest = std::max(widest, set.width);
  const float reach = 8.0f + 4.0f * widest;  // pixels
  const glm::vec2 margin(2.0f * reach / float(std::max(f.viewport.z, 1)), 2.0f * reach / float(std::max(f.viewport.w, 1)));
  return !sphereOutsideView(m.placed(f.camera), m.mesh().radius, margin);
}

class FeatureLinesFeature final : public Feature {
  // The objects' edges not yet found, found at once on every core, each object taken by the
  // next free thread: a scene's first frame waited for them one after the other (the Khronos
  // engine's 67 objects: docs/performance-history.md, "Start-up").
  static void buildEdges(FrameView& f) {
    std::vector<LinePass*> pending;
    f.scene.forEach([&](Model& m) {
      if (inView(f, m) && m.lines().needsEdges(f.settings.lines)) pending.push_back(&m.lines());
    });
    if (pending.empty()) return;
    std::atomic<std::size_t> next{0};
    parallelChunks(pending.size(), workerCount(), [&](std::size_t, std::size_t, int) {
      for (std::size_t i = next++; i < pending.size(); i = next++) pending[i]->buildEdges();
    }, 1);
    f.stats.meshCachesBuilt += static_cast<int>(pending.size());
  }

 public:
  explicit FeatureLinesFeature(std::shared_ptr<StrokeTextures> textures) : textures_(std::move(textures)) {}
  const char* name() const override { return "feature lines"; }
  bool active(const FrameView& f) const override { return f.settings.lines.edgeKinds(); }
  // The lines found, their chains' parameters continuing the last frame's.
  Status follow(FrameView& f) override {
    buildEdges(f);
    f.scene.forEach([&](Model& m) {
      if (inView(f, m)) m.lines().update(m.placed(f.camera), f.settings.lines, f.viewport, f.stats);
    });
    return okStatus();
  }
  Status drawOver(FrameView& f) override {
    const LineSettings& ls = f.settings.lines;
    (void)follow(f);
    // The surfaces' layers, once, as deep as the sets that limit hidden parts' occlusion ask.
    int levels = 0;
    for (const LineSet& set : ls.sets)
      if (set.visibility != LineSet::Visibility::Visible) levels = std::max(levels, set.occlusion);
    if (levels > 0)
      if (Status st = layers_.build(levels, f.scene.placed(f.camera), f.scene.bounds().w, f.viewport, f.programs, f.stats); !st) return st;
    // The base style, then each set in order, each on every model before the next: a later set
    // lies over an earlier one on every object, as a later layer does.
    Status result = okStatus();
    for (int layer = -1; layer < int(ls.sets.size()) && result; ++layer)
      f.scene.forEach([&](Model& m) {
        if (!result || !inView(f, m)) return;
        if (std::optional<LineStyle> style = lineStyleLayer(ls, layer, &m.name())) {
          result = prepareStyle(*style, *textures_, f);
          if (levels > 0) style->layers = &layers_;
          if (result) result = m.lines().drawStyle(*style, m.placed(f.camera), f.viewport, f.programs, f.stats);
        }
      });
    return result;
  }

 private:
  std::shared_ptr<StrokeTextures> textures_;
  OcclusionLayers layers_;
};

class IntersectionLinesFeature final : public Feature {
 public:
  explicit IntersectionLinesFeature(std::shared_ptr<StrokeTextures> textures) : textures_(std::move(textures)) {}
  const char* name() const override { return "intersection lines"; }
  bool active(const FrameView& f) const override { return (f.settings.lines.drawnKinds() & 16u) && !f.scene.empty(); }
  // Found again only when the scene changed (objects, their places or their pose), their
  // chains' parameters continuing the last pose's.
  Status follow(FrameView& f) override {
    if (!vao_ || f.scene.version() != sceneVersion_) {
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<FeatureLine> lines = sceneIntersectionLines(f.scene);
      if (!vao_) {
        vao_ = gl::createVertexArray();
        buffer_ = gl::createBuffer();
      }
      const auto& chained = chains_.update(lines);
      gl::uploadBuffer(buffer_, chained.data(), chained.size() * sizeof(ChainedLine), GL_STATIC_DRAW);
      count_ = lines.size();
      sceneVersion_ = f.scene.version();
      ++f.stats.intersectionSearches;
      ++f.stats.bufferUploads;
      f.stats.cpuLinesMs += msSince(t0);
    }
    return okStatus();
  }
  Status drawOver(FrameView& f) override {
    (void)follow(f);
    // World space: the scene's camera places them.
    for (LineStyle& style : lineStyles(f.settings.lines, nullptr))
      if (style.kinds & 16u) {
        if (Status st = prepareStyle(style, *textures_, f); !st) return st;
        if (Status st = drawLineRanges({{&buffer_, 0, count_}}, f.camera, style, f.viewport, vao_, f.programs, f.stats); !st) return st;
      }
    return okStatus();
  }

 private:
  std::shared_ptr<StrokeTextures> textures_;
  gl::VertexArray vao_;
  gl::Buffer buffer_;
  LineChains chains_{1e-4f};  // world units: vertices this near continue the last pose's strokes
  std::size_t count_ = 0;
  unsigned sceneVersion_ = 0;
};

// The files' own points and lines (glTF POINTS and LINES primitives: Mesh::dots and segments),
// drawn whatever kinds of feature line the settings draw: they are part of the model, in the
// outlines' ink and width.
class MarksFeature final : public Feature {
 public:
  const char* name() const override { return "points and lines"; }
  bool active(const FrameView& f) const override {
    bool any = false;
    f.scene.forEach([&](const Model& m) { any = any || m.mesh().hasMarks(); });
    return any;
  }
  Status drawOver(FrameView& f) override {
    Status result = okStatus();
    f.scene.forEach([&](Model& m) {
      if (result && m.mesh().hasMarks() && inView(f, m))
        result = m.lines().drawMarks(LineStyle::base(f.settings.lines, &m.name()), m.placed(f.camera), f.viewport, f.programs, f.stats);
    });
    return result;
  }
};

}  // namespace

void addLinesFeatures(std::vector<std::unique_ptr<Feature>>& features) {
  features.push_back(std::make_unique<OutlinesFeature>());
  features.push_back(std::make_unique<ImageEdgesFeature>());
  // Line sets' stroke textures, loaded once for both kinds of line.
  auto strokeTextures = std::make_shared<StrokeTextures>();
  features.push_back(std::make_unique<FeatureLinesFeature>(strokeTextures));
  features.push_back(std::make_unique<IntersectionLinesFeature>(strokeTextures));
  features.push_back(std::make_unique<MarksFeature>());
}

// Object-space lines are found on the CPU's pose.
void LinesNeeds(const RenderSettings& s, FrameNeeds& needs) { needs.cpuPose = needs.cpuPose || s.lines.drawnKinds() != 0; }

}  // namespace npr
