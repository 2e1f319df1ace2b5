// A minimal data-parallel loop: splits [0, n) into one contiguous chunk per hardware thread
// (contiguous chunks keep each thread's memory traffic sequential).
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace npr {

inline int workerCount() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

// fn(begin, end, chunkIndex) runs on `chunks` threads (the calling thread takes chunk 0), at
// most one per 32768 items: a thread is started per call, which cost more than it saved on the
// per-triangle work of a scene's small objects (bench_scene, 16 objects of 20,480 triangles:
// 1-4% of the frame against one per 4096). Items that are each long work (whole tasks, not
// triangles) pass a smaller `minPerChunk`.
template <class Fn>
void parallelChunks(std::size_t n, int chunks, Fn&& fn, std::size_t minPerChunk = 32768) {
  minPerChunk = std::max<std::size_t>(1, minPerChunk);
  chunks = std::max(1, std::min<int>(chunks, static_cast<int>((n + minPerChunk - 1) / minPerChunk)));
  if (chunks == 1) {
    fn(std::size_t(0), n, 0);
    return;
  }
  std::vector<std::thread> threads;
  threads.reserve(static_cast<size_t>(chunks - 1));
  const std::size_t step = (n + static_cast<size_t>(chunks) - 1) / static_cast<size_t>(chunks);
  for (int c = 1; c < chunks; ++c) {
    const std::size_t b = std::min(n, step * static_cast<size_t>(c)), e = std::min(n, b + step);
    threads.emplace_back([&fn, b, e, c] { fn(b, e, c); });
  }
  fn(std::size_t(0), std::min(n, step), 0);
  for (auto& t : threads) t.join();
}

}  // namespace npr
