// Where a frame poses its deforming meshes (see frame_needs.h).
#include "renderer/frame/frame_needs.h"

namespace npr {

PoseTargets poseTargets(const FrameNeeds& needs, PosePlacement deform, bool softwareRasterizer) {
  PoseTargets t;
  t.cpu = deform == PosePlacement::Cpu || needs.cpuPose;
  t.gpu = deform == PosePlacement::Gpu || (deform == PosePlacement::Auto && (!t.cpu || !softwareRasterizer));
  return t;
}

}  // namespace npr
