// The process heap's policy for frame loops. Mesa's software rasterizer (llvmpipe) allocates
// its per-frame binning memory (about 2 MB for a bunny frame at 1280x720, far more on large
// meshes) in blocks under glibc's mmap threshold, and frees it when the frame is rasterized;
// glibc then trims the top of the heap back to the system, so every frame faults the same pages
// in again and the kernel zeroes them. Keeping freed memory in the heap removes that: the
// stencil path's bunny frame 13.3-14.3 ms -> 9.3-9.7 ms in the viewer, and the benchmarks'
// interleaved rows no longer pay for the row before them (README, "Measuring").
#pragma once

namespace npr {

// Keeps freed heap memory for reuse instead of returning it to the system (glibc's
// M_TRIM_THRESHOLD; a no-op elsewhere). Call once, before the first frame, from a program's
// main: it is the program's policy, not the renderer's.
void keepFreedHeapMemory();

}  // namespace npr
