// The program and uniforms of a GPU-lit mesh pass (mesh.vert + mesh.frag lighting on the GPU):
// lights or the mesh's own materials, shadow maps, a palette, and what the active features add
// (SurfaceInput: baked and screen-space occlusion, the ground's shadow texture). Shared by the
// single-pass paths (shaded_path.h) and the control-image palettes drawn over any path
// (passes/control_palette_pass.h), so both light a pixel the same way.
#pragma once

#include "renderer/frame/frame_context.h"

namespace npr {

// Whether `shading` lights per pixel (what per-pixel inputs, screen-space occlusion and the
// ground's shadow texture, apply to).
inline bool shadesPerPixel(gl::MeshShading shading) {
  return shading == gl::MeshShading::Pixel || shading == gl::MeshShading::Smooth || shading == gl::MeshShading::Phong;
}
// The variant for `shading` in this frame, reading `palette` (null: a shading with no palette),
// with the features' inputs (FrameContext::inputs) added.
gl::MeshProgram litMeshProgram(const FrameContext& frame, gl::MeshShading shading, const GpuPalette* palette);
// Uses the program and sets everything that variant reads.
void bindLitMesh(const FrameContext& frame, gl::ShaderProgram& program, const gl::MeshProgram& variant, const GpuPalette* palette);

}  // namespace npr
