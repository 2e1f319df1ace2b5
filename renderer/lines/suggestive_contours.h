// Suggestive contours (DeCarlo, Finkelstein, Rusinkiewicz and Santella 2003): the lines where a
// contour would appear under a small change of view, drawn as illustrators draw the folds and
// hollows a silhouette does not reach. They are the zeros of the radial curvature kappa_r (the
// normal curvature along w, the view vector projected into the tangent plane) where its
// derivative along w is positive, on surfaces facing the eye.
//
// The curvature is estimated once per mesh (orientation/principal_curvature.h, the same
// estimate the hatching field starts from, on the welded surface); each view then evaluates
// kappa_r per vertex, finds its zero crossing in each front face (linear along the edges), and
// keeps the segment where the face's gradient of kappa_r along w passes a threshold, which
// drops the noise of nearly flat regions (DeCarlo et al.'s t_d, here relative to the mesh's
// size so one value suits every model). Each line's ink fades in from 0 at the threshold to
// full at twice it, and likewise from the facing limit: a contour appears gradually as the view
// turns instead of popping in (DeCarlo, Finkelstein and Rusinkiewicz 2004 fade them so).
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/lines/feature_edges.h"
#include "renderer/mesh/mesh.h"
#include "renderer/orientation/principal_curvature.h"

namespace npr {

class SuggestiveContours {
 public:
  // The derivative threshold D_w kappa_r x radius^2 (t_d), and the smallest n.v (unit view
  // vector) kept: near the silhouette the estimate is noise.
  static constexpr float kDefaultThreshold = 1.0f, kMinFacing = 0.08f;

  explicit SuggestiveContours(const Mesh& mesh);
  // The mesh was deformed (same vertices and faces): the curvature is estimated again on the
  // next lines().
  void geometryChanged() { curvature_.reset(); }
  // The segments seen from `eye` (object space), kind EdgeKind::Suggestive.
  const std::vector<FeatureLine>& lines(const glm::vec3& eye, float threshold = kDefaultThreshold);


 private:
  const Mesh* mesh_;
  std::unique_ptr<PrincipalCurvatures> curvature_;
  float radius_ = 1.0f;
  std::vector<float> radial_, facing_;
  std::vector<glm::vec3> tangentView_;  // w per welded vertex
  std::vector<FeatureLine> lines_;
};

}  // namespace npr
