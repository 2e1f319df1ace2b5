// Heap policy for frame loops (see heap_policy.h).
#include "renderer/core/heap_policy.h"

#include <cstdlib>  // defines __GLIBC__ where the C library is glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace npr {

void keepFreedHeapMemory() {
#if defined(__GLIBC__)
  // 1 GiB: above any frame's transient memory, so the heap's top is never handed back between
  // frames. This also fixes glibc's mmap threshold at its default (128 KiB): larger blocks
  // (images, meshes) are still mapped and returned to the system whole when freed.
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

void releaseFreedHeapMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace npr
