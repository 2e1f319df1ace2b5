// The feature table (see feature.h): one row per feature folder, in the order the frame calls
// them. Adding a feature is its folder and a row here.
#include "renderer/features/feature.h"

namespace npr {

// Each folder's row (its add and needs functions, defined in the folder).
#define NPR_FEATURE(folder)                                                          \
  void add##folder##Features(std::vector<std::unique_ptr<Feature>>& features);      \
  void folder##Needs(const RenderSettings& settings, FrameNeeds& needs);
NPR_FEATURE(Shadows)
NPR_FEATURE(Occlusion)
NPR_FEATURE(Strokes)
NPR_FEATURE(Lines)
NPR_FEATURE(DepthCue)
NPR_FEATURE(Vignette)
#undef NPR_FEATURE

const std::vector<FeatureRow>& featureTable() {
  static const std::vector<FeatureRow> table = {
      {addShadowsFeatures, ShadowsNeeds},      // maps before anything reads them
      {addOcclusionFeatures, OcclusionNeeds},  // per-vertex bake once per model; per-pixel after the clear
      {addStrokesFeatures, StrokesNeeds},      // over the surfaces: strokes, then lines
      {addLinesFeatures, LinesNeeds},
      {addDepthCueFeatures, DepthCueNeeds},    // fades what is drawn with distance
      {addVignetteFeatures, VignetteNeeds},    // last: fades the frame's edges into the paper
  };
  return table;
}

std::vector<std::unique_ptr<Feature>> makeFeatures() {
  std::vector<std::unique_ptr<Feature>> features;
  for (const FeatureRow& row : featureTable()) row.add(features);
  return features;
}

void featureNeeds(const RenderSettings& settings, FrameNeeds& needs) {
  for (const FeatureRow& row : featureTable()) row.needs(settings, needs);
}

}  // namespace npr
