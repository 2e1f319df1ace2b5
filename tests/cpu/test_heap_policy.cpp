// CPU tier: the frame loops' heap policy (renderer/core/heap_policy.h). Memory freed at the top
// of the heap stays in the process once the policy is set, where glibc's default hands it back
// to the system (and the next frame faults it in again).
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include <unistd.h>

#include "renderer/core/heap_policy.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace npr {
namespace {

#if !defined(__SANITIZE_ADDRESS__) && defined(__GLIBC__)
// How far the heap's top moves when 4 MB in blocks of 64 KB (under glibc's mmap threshold, as
// llvmpipe's binning blocks are) are allocated, touched and freed again: 0 if it was kept.
long heapShrinkAfterFree() {
  std::vector<void*> blocks;
  for (int i = 0; i < 64; ++i) {
    blocks.push_back(std::malloc(64 * 1024));
    static_cast<char*>(blocks.back())[0] = 1;
  }
  const char* top = static_cast<const char*>(sbrk(0));
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) std::free(*it);
  return static_cast<long>(top - static_cast<const char*>(sbrk(0)));
}
#endif

TEST(HeapPolicy, FreedMemoryStaysInTheHeap) {
#if defined(__SANITIZE_ADDRESS__) || !defined(__GLIBC__)
  GTEST_SKIP() << "the sanitizers' allocator (or a C library other than glibc) has no heap top to trim";
#else
  // The control: with glibc's default threshold the freed top is handed back.
  ASSERT_EQ(mallopt(M_TRIM_THRESHOLD, 128 * 1024), 1);
  EXPECT_GT(heapShrinkAfterFree(), 1024 * 1024) << "the test's premise: glibc trims the heap by default";
  keepFreedHeapMemory();
  EXPECT_EQ(heapShrinkAfterFree(), 0);
#endif
}

}  // namespace
}  // namespace npr
