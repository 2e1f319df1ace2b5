// The feature table (see feature.h): one row per feature, in the order the frame calls them.
// Adding a feature is its folder and a row here.
#include "renderer/features/feature.h"

#include "renderer/lines/stroke_textures.h"

namespace npr {

std::unique_ptr<Feature> makeShadowsFeature();
std::unique_ptr<Feature> makeBakedOcclusionFeature();
std::unique_ptr<Feature> makeScreenOcclusionFeature();
std::unique_ptr<Feature> makeStrokesFeature();
std::unique_ptr<Feature> makeOutlinesFeature();
std::unique_ptr<Feature> makeImageEdgesFeature();
std::unique_ptr<Feature> makeFeatureLinesFeature(std::shared_ptr<StrokeTextures> textures);
std::unique_ptr<Feature> makeIntersectionLinesFeature(std::shared_ptr<StrokeTextures> textures);
std::unique_ptr<Feature> makeDepthCueFeature();

std::vector<std::unique_ptr<Feature>> makeFeatures() {
  std::vector<std::unique_ptr<Feature>> f;
  f.push_back(makeShadowsFeature());         // maps before anything reads them
  f.push_back(makeBakedOcclusionFeature());  // per-vertex bake, once per model
  f.push_back(makeScreenOcclusionFeature()); // per-pixel, after the clear
  f.push_back(makeStrokesFeature());         // over the surfaces: strokes, then lines
  f.push_back(makeOutlinesFeature());
  f.push_back(makeImageEdgesFeature());
  // Line sets' stroke textures, loaded once for both kinds of line.
  auto strokeTextures = std::make_shared<StrokeTextures>();
  f.push_back(makeFeatureLinesFeature(strokeTextures));
  f.push_back(makeIntersectionLinesFeature(strokeTextures));
  f.push_back(makeDepthCueFeature());        // last: fades what is drawn
  return f;
}

}  // namespace npr
