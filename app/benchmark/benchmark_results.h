// What --benchmark measures per configuration (model, palette, match mode) and per path:
// speed, accuracy against the independent reference, temporal stability, the static-frame
// counters and the cost of lighting features. Filled by benchmark_run.cpp, written out by
// writeBenchmarkReport.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/palette/palette.h"
#include "renderer/paths/path_table.h"

namespace npr {

// Mean, maximum and an approximate 95th percentile (a fine histogram) of many values.
class ErrorStats {
 public:
  explicit ErrorStats(double range = 1.0) : range_(range), bins_(8192, 0) {}
  void add(double v) {
    sum_ += v;
    ++count_;
    max_ = std::max(max_, v);
    const size_t b = std::min(bins_.size() - 1, static_cast<size_t>(v / range_ * double(bins_.size())));
    ++bins_[b];
  }
  double mean() const { return count_ ? sum_ / double(count_) : 0.0; }
  double max() const { return max_; }
  double p95() const {
    std::uint64_t seen = 0;
    for (size_t b = 0; b < bins_.size(); ++b) {
      seen += bins_[b];
      if (double(seen) >= 0.95 * double(count_)) return double(b + 1) / double(bins_.size()) * range_;
    }
    return max_;
  }

 private:
  double range_, sum_ = 0.0, max_ = 0.0;
  std::uint64_t count_ = 0;
  std::vector<std::uint64_t> bins_;
};

struct PathResult {
  RenderPath path;
  // speed
  double medianMs = 0, p95Ms = 0, cpuMs = 0, gpuMs = -1, xReference = 0;
  // accuracy
  ErrorStats error;
  std::uint64_t pixels = 0, mismatched = 0, compared = 0, jumps = 0, pops = 0;
  explicit PathResult(RenderPath p, double range) : path(p), error(range) {}
};

struct ConfigResult {
  std::string model, palette;
  MatchMode mode;
  std::string errorUnit;
  std::vector<PathResult> paths;
  std::uint64_t nonFinite = 0;
  std::vector<std::string> failures;  // renders and state changes that returned an error
  int staticFrames = 0, staticRecomputes = 0, staticUploads = 0, staticBuilds = 0;
  double lightMinimalMs = 0, lightFullMs = 0;
};

// results.csv, results.md and one gnuplot plot (PNG) per configuration in `dir`.
void writeBenchmarkReport(const std::vector<ConfigResult>& results, const std::filesystem::path& dir, glm::ivec2 size,
                          int frames, const std::string& glDescription);

}  // namespace npr
