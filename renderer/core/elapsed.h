// Milliseconds since a steady-clock time point: how every CPU timing in the project is read
// (frame, shading, lines, loading, benchmarks).
#pragma once

#include <chrono>

namespace npr {

inline double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace npr
