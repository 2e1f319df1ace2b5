// What the last frame did. The counters are zero on frames where nothing they depend on
// changed (the benchmark and the overlay show them; tests assert it).
#pragma once

namespace npr {

struct FrameStats {
  double cpuShadingMs = 0.0;   // per-triangle lighting, matching and bucketing
  double cpuFrameMs = 0.0;     // everything render() did on the CPU
  double gpuMs = -1.0;         // GPU time of the most recent frame whose timer query finished
  int nonEmptyBuckets = 0;
  int lightingRecomputes = 0;  // per-triangle shading runs
  int modelsLitAhead = 0;      // of them, a scene's models lit side by side before drawing (Renderer::prepareTriangleShading)
  int bufferUploads = 0;       // mesh, bucket, per-triangle entry and LUT uploads
  int shaderBuilds = 0;
  int lutBuilds = 0;
  int drawCalls = 0;
  int lines = 0;               // feature lines drawn
  double cpuLinesMs = 0.0;     // silhouette extraction
  int intersectionSearches = 0;  // the scene's intersection lines found again (its objects or pose changed)
  double cpuPatternMs = 0.0;   // the anchored pattern's similarity fit
  double cpuToneMs = 0.0;      // the automatic tone range's estimate (palette/tone_range.h)
  int patternSamples = 0;      // samples the fit used (visible in both frames)
  double cpuFieldMs = 0.0;     // the hatching direction field, on the frame that computed it
  // Per-mesh caches computed this frame (the direction field, the feature edges' adjacency,
  // the strokes' seeds): a new mesh or setting's, never a new pose's (animation/deformation.h).
  int meshCachesBuilt = 0;
  // Poses made this frame (animation/gpu_deformation.h): on the GPU into the vertex buffers,
  // and on the CPU (the mesh as per-triangle lighting, lines and strokes read it, then uploaded
  // unless the GPU posed it too), with the CPU's time.
  int gpuPoses = 0;
  int cpuPoses = 0;
  double cpuPoseMs = 0.0;
  int shadowMapRenders = 0;    // frames whose shadow maps were redrawn (a light or the scene moved)
  int shadowLayers = 0;        // shadow map layers in use (one per light, six for a point light among the casters)
  // Per-pixel surface buffers that a mesh pass writes beside its colour, sharing the bound
  // framebuffer's depth and stencil (the stencil path's stroke angles and object pattern
  // coordinates, the turn resolve's angles and entries): how many the frame needed, and how
  // many of the stencil path's took a geometry pass of their own because the framebuffer could
  // not be shared (the window's own cannot; the turn resolve then turns in the mesh pass).
  int surfaceBuffers = 0;
  int surfaceBufferPasses = 0;
  bool backFacesCulled = false;  // the mesh passes dropped back faces (render_pass.h: FrameContext)
  int surfacesCulled = 0;        // objects or batches wholly outside the view, not drawn (scene_surfaces.h)

  // Clears the per-frame figures; gpuMs stays until a newer timer query finishes.
  void startFrame() {
    const double gpu = gpuMs;
    *this = FrameStats{};
    gpuMs = gpu;
  }
};

}  // namespace npr
