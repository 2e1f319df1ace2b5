// The occlusion folder's row of the feature table (features/feature_table.cpp): the bake per
// vertex, then the estimate per pixel after the clear. Neither reads a pose on the CPU.
#include <memory>
#include <vector>

#include "renderer/features/feature.h"

namespace npr {

std::unique_ptr<Feature> makeBakedOcclusionFeature();
std::unique_ptr<Feature> makeScreenOcclusionFeature();

void addOcclusionFeatures(std::vector<std::unique_ptr<Feature>>& features) {
  features.push_back(makeBakedOcclusionFeature());
  features.push_back(makeScreenOcclusionFeature());
}

// The bake is each object's own (it shades by its own vertices): the objects draw themselves.
void OcclusionNeeds(const RenderSettings& s, FrameNeeds& needs) {
  needs.objectSurfaces = needs.objectSurfaces || (s.occlusion && s.occlusionMethod == OcclusionMethod::Baked);
}

}  // namespace npr
