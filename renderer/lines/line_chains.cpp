// Chaining feature lines and carrying their parameters between frames (see line_chains.h).
#include "renderer/lines/line_chains.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

namespace npr {
namespace {

ChainKey exactKey(const glm::vec3& p) {
  ChainKey k{};
  for (int c = 0; c < 3; ++c) {
    const float v = p[c] + 0.0f;  // -0 and 0 join
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    k[std::size_t(c)] = bits;
  }
  return k;
}

double median(std::vector<float>& v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

std::vector<std::vector<ChainStep>> chainSegments(const std::vector<ChainKey>& ends) {
  const std::size_t n = ends.size() / 2;
  // Ends sorted by key: the ends that join are neighbours. at[e]: the first of end e's group in
  // `order`; a group of two is a chain running on.
  std::vector<std::uint32_t> order(2 * n);
  for (std::uint32_t e = 0; e < 2 * n; ++e) order[e] = e;
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return ends[x] < ends[y] || (ends[x] == ends[y] && x < y); });
  std::vector<std::uint32_t> groupStart(2 * n), groupSize(2 * n), at(2 * n);
  for (std::size_t k = 0; k < order.size();) {
    std::size_t m = k;
    while (m < order.size() && ends[order[m]] == ends[order[k]]) ++m;
    for (std::size_t q = k; q < m; ++q) {
      at[order[q]] = std::uint32_t(k);
      groupStart[q] = std::uint32_t(k);
      groupSize[q] = std::uint32_t(m - k);
    }
    k = m;
  }
  // The segments meeting at end e's place (a segment whose two ends coincide counts once).
  const auto meeting = [&](std::uint32_t e) { return groupSize[at[e]]; };
  const auto other = [&](std::uint32_t e) {  // the other segment at e's place, when two meet
    const std::uint32_t g = at[e];
    const std::uint32_t a = order[g], b = order[g + 1];
    return (a / 2 == e / 2 ? b : a);
  };
  std::vector<char> used(n, 0);
  std::vector<std::vector<ChainStep>> chains;
  const auto walk = [&](std::uint32_t first, bool reversed) {
    std::vector<ChainStep> c;
    std::uint32_t s = first;
    while (true) {
      used[s] = 1;
      c.push_back({s, reversed});
      const std::uint32_t end = 2 * s + (reversed ? 0 : 1);
      if (meeting(end) != 2) break;  // a free end or a junction: the chain stops
      const std::uint32_t next = other(end);
      const std::uint32_t t = next / 2;
      if (t == s || used[t]) break;
      reversed = next % 2 == 1;  // walked from the end it shares
      s = t;
    }
    chains.push_back(std::move(c));
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    if (used[i]) continue;
    if (meeting(2 * i) != 2) walk(i, false);
    else if (meeting(2 * i + 1) != 2) walk(i, true);
  }
  for (std::uint32_t i = 0; i < n; ++i)
    if (!used[i]) walk(i, false);  // loops
  return chains;
}

std::uint64_t LineChains::cell(const glm::vec3& p) const {
  const glm::vec3 q = glm::floor(p / cellSize());
  const auto c = [](float v) { return std::uint64_t(std::int64_t(std::clamp(v, -1e6f, 1e6f)) & 0x1FFFFF); };
  return c(q.x) | c(q.y) << 21 | c(q.z) << 42;
}

const LineChains::Sample* LineChains::nearest(const glm::vec3& p, std::int64_t preferred) const {
  const Sample* best = nullptr;
  float bestD = tolerance_ * tolerance_;
  bool bestPreferred = false;
  // Cells are 16 tolerances wide: only the neighbours across a face within a tolerance of p.
  const float size = cellSize();
  const glm::vec3 inCell = p / size - glm::floor(p / size);
  const float near = tolerance_ / size;
  glm::ivec3 lo(0), hi(0);
  for (int c = 0; c < 3; ++c) {
    if (inCell[c] < near) lo[c] = -1;
    if (inCell[c] > 1.0f - near) hi[c] = 1;
  }
  for (int dz = lo.z; dz <= hi.z; ++dz)
    for (int dy = lo.y; dy <= hi.y; ++dy)
      for (int dx = lo.x; dx <= hi.x; ++dx) {
        const auto it = grid_.find(cell(p + size * glm::vec3(dx, dy, dz)));
        if (it == grid_.end()) continue;
        for (std::uint32_t k = it->second.first; k < it->second.second; ++k) {
          const Sample& sample = samples_[k];
          const glm::vec3 d = sample.position - p;
          const float d2 = glm::dot(d, d);
          if (d2 > tolerance_ * tolerance_) continue;
          // Several chains may have had a vertex here (a junction, a zigzag's corner): the one the
          // chain's previous vertex matched wins, then the nearest.
          const bool isPreferred = std::int64_t(sample.chain) == preferred;
          if ((isPreferred && !bestPreferred) || (isPreferred == bestPreferred && d2 <= bestD)) {
            bestD = d2;
            best = &sample;
            bestPreferred = isPreferred;
          }
        }
      }
  return best;
}

const std::vector<ChainedLine>& LineChains::update(const std::vector<FeatureLine>& lines, float jump) {
  out_.clear();
  out_.reserve(lines.size());
  coherence_ = ChainCoherence{};
  std::vector<Sample> next;
  next.reserve(lines.size() + lines.size() / 4);
  std::vector<char> seen(previousChains_, 0);
  double shift = 0.0;
  std::uint32_t chainId = 0;
  std::vector<glm::vec3> verts;
  std::vector<float> arc, params;
  std::vector<char> along;
  std::vector<std::uint32_t> segs;  // per edge of the chain, its segment in the run
  std::vector<std::int64_t> group;
  struct Fit {
    std::vector<float> votes;
    float offset, sign;
  };
  std::vector<Fit> fits;
  std::map<std::uint32_t, int> way;  // per previous chain: matched vertices running its way minus those against
  shifts_.clear();
  std::vector<const Sample*> match;
  std::vector<ChainKey> ends;
  for (std::size_t b = 0; b < lines.size();) {
    std::size_t e = b;
    while (e < lines.size() && lines[e].kind == lines[b].kind) ++e;
    ends.clear();
    for (std::size_t i = b; i < e; ++i) {
      ends.push_back(exactKey(lines[i].a));
      ends.push_back(exactKey(lines[i].b));
    }
    for (const std::vector<ChainStep>& chain : chainSegments(ends)) {
      // The chain's vertices, and per edge whether its segment runs that way in `lines`.
      verts.clear();
      along.clear();
      segs.clear();
      const FeatureLine& head = lines[b + chain.front().segment];
      verts.push_back(chain.front().reversed ? head.b : head.a);
      for (const ChainStep& st : chain) {
        const FeatureLine& l = lines[b + st.segment];
        verts.push_back(st.reversed ? l.a : l.b);
        along.push_back(!st.reversed);
        segs.push_back(st.segment);
      }
      const std::size_t nv = verts.size();
      const bool closed = nv > 2 && exactKey(verts.front()) == exactKey(verts.back());
      const auto tangent = [&](std::size_t i) {
        const glm::vec3 d = closed && (i == 0 || i + 1 == nv) ? verts[1] - verts[nv - 2]
                                                             : verts[std::min(i + 1, nv - 1)] - verts[i == 0 ? 0 : i - 1];
        const float len = glm::length(d);
        return len > 0.0f ? d / len : glm::vec3(0.0f);
      };
      match.assign(nv, nullptr);
      std::size_t same = 0, opposite = 0;
      // The previous chain being followed stays preferred over a vertex or two that only another
      // chain had (a corner both passed).
      std::int64_t preferred = -1;
      int elsewhere = 0;
      for (std::size_t i = 0; i < nv; ++i) {
        const Sample* m = samples_.empty() ? nullptr : nearest(verts[i], preferred);
        if (m && std::int64_t(m->chain) != preferred && (preferred < 0 || ++elsewhere >= 2)) {
          preferred = m->chain;
          elsewhere = 0;
        } else if (m) {
          elsewhere = 0;
        }
        if (!m) continue;
        match[i] = m;
        if (m->chain < seen.size()) seen[m->chain] = 1;
        (glm::dot(tangent(i), m->direction) >= 0.0f ? same : opposite) += 1;
      }
      if (coherent_ && closed && same + opposite > 0) {
        // A loop is turned to run the way it ran, and to start where its parameter started:
        // at the matched vertex with the least parameter then (its seam stays put).
        if (opposite > same) {
          std::reverse(verts.begin(), verts.end());
          std::reverse(match.begin(), match.end());
          std::reverse(along.begin(), along.end());
          std::reverse(segs.begin(), segs.end());
          for (std::size_t e = 0; e < along.size(); ++e) along[e] = !along[e];
        }
        std::size_t start = 0;
        for (std::size_t i = 0; i + 1 < nv; ++i)
          if (match[i] && (!match[start] || match[i]->param < match[start]->param)) start = i;
        verts.pop_back();
        match.pop_back();
        std::rotate(verts.begin(), verts.begin() + std::ptrdiff_t(start), verts.end());
        std::rotate(match.begin(), match.begin() + std::ptrdiff_t(start), match.end());
        std::rotate(along.begin(), along.begin() + std::ptrdiff_t(start), along.end());
        std::rotate(segs.begin(), segs.begin() + std::ptrdiff_t(start), segs.end());
        verts.push_back(verts.front());
        match.push_back(nullptr);  // the seam's vertex votes once, at the start
      }
      arc.assign(nv, 0.0f);
      for (std::size_t i = 1; i < nv; ++i) arc[i] = arc[i - 1] + glm::length(verts[i] - verts[i - 1]);
      // Each vertex where the last frame had a chain votes for the offset that gives it its
      // parameter then (running the way that chain ran). Consecutive votes that agree (within
      // `jump`) form a run with one offset; where they disagree (two strokes joined, or the
      // chain took another way at a junction) a new run starts: the parameter jumps once there
      // instead of one part crawling. Unmatched vertices take a neighbouring run's.
      way.clear();
      for (std::size_t i = 0; i < nv; ++i)
        if (match[i]) way[match[i]->chain] += glm::dot(tangent(i), match[i]->direction) >= 0.0f ? 1 : -1;
      group.assign(nv, -1);
      fits.clear();
      float lastVote = 0.0f;
      std::uint32_t lastChain = 0;
      for (std::size_t i = 0; i < nv; ++i) {
        if (!match[i]) continue;
        const float sign = way[match[i]->chain] >= 0 ? 1.0f : -1.0f;
        const float vote = match[i]->param - sign * arc[i];
        if (fits.empty() || match[i]->chain != lastChain || std::fabs(vote - lastVote) > jump) fits.push_back({{}, 0.0f, sign});
        fits.back().votes.push_back(vote);
        group[i] = std::int64_t(fits.size() - 1);
        lastVote = vote;
        lastChain = match[i]->chain;
      }
      for (std::size_t i = 1; i < nv; ++i)
        if (group[i] < 0) group[i] = group[i - 1];
      for (std::size_t i = nv - 1; i-- > 0;)
        if (group[i] < 0) group[i] = group[i + 1];
      for (Fit& fit : fits) {
        if (coherent_) fit.offset = float(median(fit.votes));
        else fit.sign = 1.0f;
      }
      if (fits.empty()) ++coherence_.appeared;
      else coherence_.jumps += fits.size() - 1;
      const auto paramOf = [&](std::size_t i, std::int64_t g) { return g < 0 ? arc[i] : fits[std::size_t(g)].offset + fits[std::size_t(g)].sign * arc[i]; };
      params.resize(nv);
      for (std::size_t i = 0; i < nv; ++i) {
        params[i] = paramOf(i, group[i]);
        if (match[i]) {
          ++coherence_.matchedVertices;
          const double d = std::fabs(double(params[i]) - double(match[i]->param));
          shift += d;
          shifts_.push_back(float(d));
        }
        if (closed && i + 1 == nv) continue;  // the seam is the start's vertex
        const float sign = group[i] < 0 ? 1.0f : fits[std::size_t(group[i])].sign;
        next.push_back({verts[i], sign * tangent(i), params[i], chainId});
      }
      // A closed loop has no ends to taper: its length is given negative.
      const float length = closed ? -arc.back() : arc.back();
      // A segment's two ends take its first vertex's part (no jump inside a segment). Each
      // keeps its own way round (the sketchy strokes' jitter hashes its ends in order).
      // Its neighbours along the chain: a loop's wrap round its seam, an open chain's ends have none.
      const auto neighbour = [&](std::size_t i, bool forward) {
        if (forward ? i + 2 < nv : i > 0) return glm::vec4(verts[forward ? i + 2 : i - 1], 1.0f);
        if (closed && nv > 3) return glm::vec4(verts[forward ? 1 : nv - 2], 1.0f);
        return glm::vec4(0.0f);
      };
      for (std::size_t i = 0; i + 1 < nv; ++i) {
        const glm::vec2 p(params[i], paramOf(i + 1, group[i]));
        const LineAttributes& at = lines[b + segs[i]].attributes;  // its ends stay its own (see above)
        const glm::vec4 before = neighbour(i, false), after = neighbour(i, true);
        if (along[i]) out_.push_back({verts[i], verts[i + 1], lines[b].kind, p, {arc[i], arc[i + 1]}, length, at, before, after});
        else out_.push_back({verts[i + 1], verts[i], lines[b].kind, {p.y, p.x}, {arc[i + 1], arc[i]}, length, at, after, before});
      }
      ++chainId;
    }
    b = e;
  }
  coherence_.chains = chainId;
  coherence_.vanished = std::size_t(std::count(seen.begin(), seen.end(), 0));
  coherence_.meanShift = coherence_.matchedVertices ? shift / double(coherence_.matchedVertices) : 0.0;
  if (!shifts_.empty()) {
    coherence_.medianShift = median(shifts_);
    const auto at90 = shifts_.begin() + std::ptrdiff_t(shifts_.size() * 9 / 10);
    std::nth_element(shifts_.begin(), at90, shifts_.end());
    coherence_.shift90 = *at90;
  }
  // Samples sorted by cell, each cell a range of them.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> byCell(next.size());
  for (std::uint32_t i = 0; i < next.size(); ++i) byCell[i] = {cell(next[i].position), i};
  std::sort(byCell.begin(), byCell.end());
  samples_.resize(next.size());
  grid_.clear();
  grid_.reserve(byCell.size());
  for (std::uint32_t k = 0; k < byCell.size(); ++k) {
    samples_[k] = next[byCell[k].second];
    auto [it, inserted] = grid_.try_emplace(byCell[k].first, k, k + 1);
    if (!inserted) it->second.second = k + 1;
  }
  previousChains_ = chainId;
  return out_;
}

}  // namespace npr
