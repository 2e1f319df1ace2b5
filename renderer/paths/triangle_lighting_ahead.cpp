// The per-triangle paths light each model's triangles on the CPU when it draws. A large model's
// lighting is split over the cores (parallel.h); a scene's small models would each light on
// one core, one after another: here they light side by side, a share of the models per core,
// before the frame draws them, and each cache then finds its lighting done and only uploads
// (bench_scene: 16 objects against one merged mesh). Only where the draw will ask for exactly
// this lighting: CPU-lit (no shadows, which Auto lights on the GPU), no baked occlusion, one tone
// range for the scene, no per-material parts; elsewhere the draw lights as before.
#include "renderer/paths/triangle_lighting_ahead.h"

#include <vector>

#include "renderer/core/parallel.h"

namespace npr {

void lightTrianglesAhead(FrameView& f) {
  const RenderSettings& s = f.settings;
  if (s.triangleLighting == TriangleLighting::Gpu || s.shadows || s.occlusion) return;
  std::vector<Model*> models;
  f.scene.forEachSurface([&](Model& m) {
    if (m.toneSlot == 0 && (m.parts().empty() || !s.materials) && f.paletteOf(m)) models.push_back(&m);
  });
  if (models.size() < 2) return;
  std::vector<FrameStats> counted(models.size());
  parallelChunks(
      models.size(), workerCount(),
      [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i) {
          Model& m = *models[i];
          const GpuPalette& p = *f.paletteOf(m);
          m.triangles().expectRows(s.paletteAxis && p.axis().rows > 1);
          m.triangles().prepare(f.lighting, m.placed(f.camera).view, *p.matcher(), p.matcherId(), counted[i], s.materials, nullptr,
                                s.occlusionStrength);
        }
      },
      1);
  for (const FrameStats& c : counted) {
    f.stats.cpuShadingMs += c.cpuShadingMs;
    f.stats.lightingRecomputes += c.lightingRecomputes;
    f.stats.modelsLitAhead += c.lightingRecomputes;
  }
}

}  // namespace npr
