// Feature lines joined into chains, each with a parameter along it, so that taper, dashes and
// stroke textures run along a whole stroke instead of restarting at every mesh edge. A chain's
// parameter is its arc length (object units) plus an offset kept from the previous frame where
// the chain persists: where its vertices lie where the last frame's chains had vertices, the
// offset is the one that gives them their previous parameters (the median of their votes; after
// Kalnins et al. 2003, who propagate stroke parameters between frames), so dashes do not crawl
// while the view turns. A chain with no such vertex starts at 0: it appeared. update() reports
// how far the parameters shifted at matched vertices and how many chains appeared and vanished.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/lines/feature_edges.h"

namespace npr {

// One segment as lines.vert reads it (line_pass.cpp's kLineStreams).
struct ChainedLine {
  glm::vec3 a, b;
  float kind;         // EdgeKind
  glm::vec2 param;    // the stroke's parameter at a and at b (object units)
  glm::vec2 arc;      // the distance along the chain from its start to a and to b
  float length;       // the chain's length; negative for a closed loop (it has no ends)
  LineAttributes attributes;  // the segment's own, as found (its ends keep their way round)
  // The chain's vertex before a and after b (w 1), or none (w 0: the chain ends or branches
  // there). lines.vert cuts the segment's quad at the joint's bisector with them, so two
  // segments' caps never cover a pixel twice and a partial coverage is not inked twice.
  glm::vec4 before{0.0f}, after{0.0f};
};

// A step of a chain: a segment, walked from its second end to its first when `reversed`.
struct ChainStep {
  std::uint32_t segment;
  bool reversed;
};
// The key of a segment's end: ends with equal keys join.
using ChainKey = std::array<std::int64_t, 3>;
// Joins segments (ends 2i and 2i + 1 of `ends`) into chains: a chain runs on while exactly two
// segments meet at an end, and starts at free ends and junctions; what is left are loops.
std::vector<std::vector<ChainStep>> chainSegments(const std::vector<ChainKey>& ends);

// How the parameters moved since the previous update.
struct ChainCoherence {
  std::size_t chains = 0;
  std::size_t matchedVertices = 0;  // vertices lying at (within the tolerance of) a previous chain's vertex
  double meanShift = 0.0;           // |parameter now - then| over them, object units
  double medianShift = 0.0, shift90 = 0.0;  // ... and their median and 90th percentile
  std::size_t jumps = 0;            // places where a chain's parameter jumps between two runs
  std::size_t appeared = 0;         // chains with no vertex where the previous frame had one
  std::size_t vanished = 0;         // previous chains with no vertex where this frame has one
};

class LineChains {
 public:
  // `tolerance`: how near (object units) a vertex must lie to a previous one to continue its
  // parameter. Not coherent: every chain starts at 0 (for comparison).
  explicit LineChains(float tolerance = 0.0f, bool coherent = true) : tolerance_(tolerance), coherent_(coherent) {}
  // Another mesh's lines: nothing carries over.
  void reset(float tolerance) {
    tolerance_ = tolerance;
    forget();
  }
  // Chains `lines` (each run of one kind apart, in their order, so ranges by kind stay valid).
  // `jump`: how far (object units; about two pixels) the parameters a persisting stroke's
  // vertices had may disagree before the stroke keeps them in two runs, the parameter jumping
  // between them, rather than move some of them.
  const std::vector<ChainedLine>& update(const std::vector<FeatureLine>& lines, float jump = 0.0f);
  const std::vector<ChainedLine>& lines() const { return out_; }
  const ChainCoherence& coherence() const { return coherence_; }
  void forget() {
    samples_.clear();
    grid_.clear();
    previousChains_ = 0;
  }

 private:
  struct Sample {
    glm::vec3 position;
    glm::vec3 direction;  // the way the parameter grows
    float param;
    std::uint32_t chain;
  };
  const Sample* nearest(const glm::vec3& p, std::int64_t preferredChain) const;
  std::uint64_t cell(const glm::vec3& p) const;

  float tolerance_;
  bool coherent_;
  std::vector<ChainedLine> out_;
  std::vector<float> shifts_;
  std::vector<Sample> samples_;
  std::size_t previousChains_ = 0;
  float cellSize() const { return 16.0f * std::max(tolerance_, 1e-7f); }
  std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> grid_;  // cell -> its samples' range
  ChainCoherence coherence_;
};

}  // namespace npr
