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
// Hands the heap's free pages back to the system now (glibc's malloc_trim, which also releases
// whole free pages inside the heap, not only its top; a no-op elsewhere). For rare events that
// free a lot, such as replacing a scene: kept memory then does not ratchet up with each load's
// transient peak (a ten-minute soak of drops grew 7-13% without it, issue 42).
void releaseFreedHeapMemory();

}  // namespace npr
