// The process heap's policy for frame loops. Mesa's software rasterizer (llvmpipe) allocates
// its per-frame binning memory (about 2 MB for a bunny frame at 1280x720, far more on large
// meshes) in blocks under glibc's mmap threshold, and frees it when the frame is rasterized;
// glibc then trims the top of the heap back to the system, so every frame faults the same pages
// in again and the kernel zeroes them. Keeping freed memory in the heap removes that: in the
// viewer at 1280x720 the stencil path's bunny frame went from 15-17 ms to 11-12 ms and the
// 871K torus through the vertex path from 179-188 ms to 92-93 ms, and the benchmarks'
// interleaved rows no longer pay for the row before them (README, "Performance and accuracy").
#pragma once

namespace npr {

// Keeps freed heap memory for reuse instead of returning it to the system (glibc's
// M_TRIM_THRESHOLD; a no-op elsewhere). Call once, before the first frame, from a program's
// main: it is the program's policy, not the renderer's.
void keepFreedHeapMemory();

}  // namespace npr
