// Anchored patterns: the per-frame similarity fit (see pattern_tracker.h).
#include "renderer/patterns/pattern_tracker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "renderer/core/elapsed.h"

namespace npr {
namespace {

// How a surface point faces the eye: n.v (its foreshortening) and its distance squared. Its
// area times nv / d2 is the screen area it covers, up to the projection's constant.
struct Facing {
  float nv, d2;
};
Facing facing(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye) {
  const glm::vec3 toEye = eye - position;
  const float d2 = glm::dot(toEye, toEye);
  return {glm::dot(normal, toEye) / std::sqrt(std::max(d2, 1e-24f)), d2};
}

}  // namespace

PatternFrame fitSimilarity(const std::vector<glm::vec2>& from, const std::vector<glm::vec2>& to, const std::vector<float>& w,
                           bool followRotation) {
  PatternFrame f;
  double sw = 0.0;
  glm::dvec2 pf(0.0), pt(0.0);
  for (std::size_t i = 0; i < from.size(); ++i) {
    sw += w[i];
    pf += double(w[i]) * glm::dvec2(from[i]);
    pt += double(w[i]) * glm::dvec2(to[i]);
  }
  if (!(sw > 0.0)) return f;
  pf /= sw;
  pt /= sw;
  double sxx = 0.0, sxy = 0.0, ssFrom = 0.0, ssTo = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const glm::dvec2 a = glm::dvec2(from[i]) - pf, b = glm::dvec2(to[i]) - pt;
    sxx += w[i] * glm::dot(a, b);
    sxy += w[i] * (a.x * b.y - a.y * b.x);
    ssFrom += w[i] * glm::dot(a, a);
    ssTo += w[i] * glm::dot(b, b);
  }
  const double theta = followRotation && (sxx != 0.0 || sxy != 0.0) ? std::atan2(sxy, sxx) : 0.0;
  const double s = ssFrom > 1e-12 && ssTo > 1e-12 ? std::sqrt(ssTo / ssFrom) : 1.0;
  const double c = std::cos(theta), sn = std::sin(theta);
  const glm::dvec2 rotated(c * pf.x - sn * pf.y, sn * pf.x + c * pf.y);
  f.rotation = static_cast<float>(theta);
  f.scale = static_cast<float>(std::isfinite(s) ? s : 1.0);
  f.translation = glm::vec2(pt - s * rotated);
  return f;
}

void PatternTracker::setMesh(const Mesh* mesh) {
  samples_.clear();
  closeUp_.clear();
  mesh_ = mesh;
  reset();
  if (!mesh || mesh->triangleCount() == 0) return;
  // Area-weighted random points (fixed seed: the same samples each time the mesh is loaded).
  const std::size_t nf = mesh->triangleCount();
  std::vector<double> cumulative(nf);
  double total = 0.0;
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t* id = &mesh->indices[f * 3];
    const glm::vec3 a = mesh->positions[id[0]], b = mesh->positions[id[1]], c = mesh->positions[id[2]];
    const double area = 0.5 * glm::length(glm::cross(glm::dvec3(b - a), glm::dvec3(c - a)));
    total += std::isfinite(area) ? area : 0.0;
    cumulative[f] = total;
  }
  if (!(total > 0.0)) return;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < kSamples; ++i) {
    const double r = u(rng) * total;
    const std::size_t f = std::min<std::size_t>(static_cast<std::size_t>(std::lower_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin()), nf - 1);
    double s = u(rng), t = u(rng);
    if (s + t > 1.0) s = 1.0 - s, t = 1.0 - t;
    const std::uint32_t* id = &mesh->indices[f * 3];
    const glm::vec3 a = mesh->positions[id[0]], b = mesh->positions[id[1]], c = mesh->positions[id[2]];
    samples_.push_back({a + float(s) * (b - a) + float(t) * (c - a), mesh->faceNormals[f], static_cast<float>(total / kSamples)});
  }
}

PatternTracker::View PatternTracker::View::of(const CameraMatrices& camera, const glm::ivec4& viewport) {
  View v;
  v.mvp = camera.projection * camera.view;
  v.eye = glm::vec3(glm::inverse(camera.view)[3]);
  v.viewport = viewport;
  return v;
}

bool PatternTracker::View::project(const glm::vec3& position, const glm::vec3& normal, glm::vec2& screen) const {
  const glm::vec4 c = mvp * glm::vec4(position, 1.0f);
  if (!(c.w > 1e-6f)) return false;
  const glm::vec3 ndc = glm::vec3(c) / c.w;
  if (std::fabs(ndc.x) > 1.0f || std::fabs(ndc.y) > 1.0f || std::fabs(ndc.z) > 1.0f) return false;
  screen = glm::vec2(viewport.x, viewport.y) + (glm::vec2(ndc) * 0.5f + 0.5f) * glm::vec2(viewport.z, viewport.w);
  // Front-facing (the far side of a closed model is hidden and moves with more parallax);
  // occlusion by other parts is not tested.
  return glm::dot(normal, glm::normalize(eye - position)) > 0.05f;
}

void PatternTracker::gather(const std::vector<Sample>& samples, const View& before, const View& now, Pairs& out) {
  out.from.clear();
  out.to.clear();
  out.weights.clear();
  for (const Sample& s : samples) {
    glm::vec2 a, b;
    if (!before.project(s.position, s.normal, a) || !now.project(s.position, s.normal, b)) continue;
    out.from.push_back(a);
    out.to.push_back(b);
    // Weighted by the pixels it stands for.
    const Facing v = facing(s.position, s.normal, now.eye);
    out.weights.push_back(s.area * v.nv / std::max(v.d2, 1e-12f));
  }
}

void PatternTracker::sampleCloseUp(const View& now) {
  closeUp_.clear();
  if (!mesh_ || mesh_->triangleCount() == 0) return;
  // Faces in front of the eye, facing it, whose screen rectangle meets the viewport, with that
  // rectangle's area inside it. At most kScanFaces faces are looked at (evenly strided), so a
  // large mesh costs a bounded scan; a close-up of it still has many faces in view.
  const std::size_t nf = mesh_->triangleCount();
  const std::size_t stride = std::max<std::size_t>(1, (nf + kScanFaces - 1) / kScanFaces);
  const glm::vec2 lo(now.viewport.x, now.viewport.y), hi = lo + glm::vec2(now.viewport.z, now.viewport.w);
  struct Candidate {
    std::size_t face;
    glm::vec2 lo, hi;
  };
  std::vector<Candidate> candidates;
  std::vector<double> cumulative;
  double total = 0.0;
  for (std::size_t f = 0; f < nf; f += stride) {
    const glm::vec3 n = mesh_->faceNormals[f];
    const std::uint32_t* id = &mesh_->indices[f * 3];
    if (n == glm::vec3(0.0f) || !(glm::dot(n, now.eye - mesh_->positions[id[0]]) > 0.0f)) continue;
    glm::vec2 bl(std::numeric_limits<float>::max()), bh(-std::numeric_limits<float>::max());
    bool front = true;
    for (int k = 0; k < 3 && front; ++k) {
      const glm::vec4 c = now.mvp * glm::vec4(mesh_->positions[id[k]], 1.0f);
      front = c.w > 1e-6f;  // a face crossing the eye's plane is left out
      if (!front) break;
      const glm::vec2 p = lo + (glm::vec2(c) / c.w * 0.5f + 0.5f) * (hi - lo);
      bl = glm::min(bl, p);
      bh = glm::max(bh, p);
    }
    bl = glm::max(bl, lo);
    bh = glm::min(bh, hi);
    if (!front || !(bh.x > bl.x && bh.y > bl.y)) continue;
    total += double(bh.x - bl.x) * double(bh.y - bl.y);
    candidates.push_back({f, bl, bh});
    cumulative.push_back(total);
  }
  if (candidates.empty() || !(total > 0.0)) return;
  // Points uniform over the pixels the candidates cover: a pixel of a candidate's rectangle,
  // cast onto the face's plane and kept if it lands inside the face. Each point then stands
  // for the same screen area, which its weight says (gather's weight is 1 at this view).
  const glm::dmat4 toWorld = glm::inverse(glm::dmat4(now.mvp));
  std::mt19937 rng(54321);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int attempt = 0; attempt < 8 * kSamples && static_cast<int>(closeUp_.size()) < kSamples; ++attempt) {
    const Candidate& c = candidates[std::min<std::size_t>(
        static_cast<std::size_t>(std::lower_bound(cumulative.begin(), cumulative.end(), u(rng) * total) - cumulative.begin()), candidates.size() - 1)];
    const glm::dvec2 px = glm::dvec2(c.lo) + glm::dvec2(u(rng), u(rng)) * glm::dvec2(c.hi - c.lo);
    const glm::dvec2 ndc = (px - glm::dvec2(lo)) / glm::dvec2(hi - lo) * 2.0 - 1.0;
    const glm::dvec4 nearP = toWorld * glm::dvec4(ndc, -1.0, 1.0), farP = toWorld * glm::dvec4(ndc, 1.0, 1.0);
    if (nearP.w == 0.0 || farP.w == 0.0) continue;
    const glm::dvec3 o = glm::dvec3(nearP) / nearP.w, d = glm::dvec3(farP) / farP.w - o;
    const std::uint32_t* id = &mesh_->indices[c.face * 3];
    const glm::dvec3 a(mesh_->positions[id[0]]), b(mesh_->positions[id[1]]), e(mesh_->positions[id[2]]);
    const glm::dvec3 n(mesh_->faceNormals[c.face]);
    const double dn = glm::dot(n, d);
    if (!(std::fabs(dn) > 1e-12)) continue;
    const glm::dvec3 p = o + d * (glm::dot(n, a - o) / dn);
    if (glm::dot(glm::cross(b - a, p - a), n) < 0.0 || glm::dot(glm::cross(e - b, p - b), n) < 0.0 || glm::dot(glm::cross(a - e, p - e), n) < 0.0) continue;
    const glm::vec3 position(p);
    const Facing v = facing(position, glm::vec3(n), now.eye);
    if (!std::isfinite(v.d2) || !(v.nv > 0.05f)) continue;
    closeUp_.push_back({position, glm::vec3(n), v.d2 / v.nv});
  }
}

const PatternFit& PatternTracker::update(const CameraMatrices& camera, const glm::ivec4& viewport, bool followRotation) {
  const auto t0 = std::chrono::steady_clock::now();
  fit_ = {};
  const View now = View::of(camera, viewport);
  if (!havePrevious_) {
    // Nothing to follow yet: the frame starts as it is.
    fit_.reset = true;
  } else {
    // The fixed samples while enough of them are in view; else points drawn from what the view
    // shows (a close-up leaves few of a few hundred spread over the model), kept while enough
    // of them stay in view and given up as soon as the fixed ones suffice again.
    gather(samples_, previous_, now, pairs_);
    if (static_cast<int>(pairs_.from.size()) < kCloseUpBelow) {
      gather(closeUp_, previous_, now, closeUpPairs_);
      if (static_cast<int>(closeUpPairs_.from.size()) < kCloseUpBelow) {
        sampleCloseUp(now);
        fit_.resampled = true;
        gather(closeUp_, previous_, now, closeUpPairs_);
      }
      if (closeUpPairs_.from.size() > pairs_.from.size()) std::swap(pairs_, closeUpPairs_);
    } else {
      closeUp_.clear();
    }
    const std::vector<glm::vec2>& from = pairs_.from;
    const std::vector<glm::vec2>& to = pairs_.to;
    const std::vector<float>& weights = pairs_.weights;
    fit_.samplesUsed = static_cast<int>(from.size());
    if (from.size() >= 3) {
      const PatternFrame m = fitSimilarity(from, to, weights, followRotation);
      double err = 0.0, sw = 0.0;
      const float c = std::cos(m.rotation), s = std::sin(m.rotation);
      for (std::size_t i = 0; i < from.size(); ++i) {
        const glm::vec2 p = m.scale * glm::vec2(c * from[i].x - s * from[i].y, s * from[i].x + c * from[i].y) + m.translation;
        err += weights[i] * double(glm::dot(p - to[i], p - to[i]));
        sw += weights[i];
      }
      fit_.residualPx = sw > 0.0 ? static_cast<float>(std::sqrt(err / sw)) : 0.0f;
      // Accumulate: the new frame is this frame's motion after the old one.
      const float cf = std::cos(m.rotation), sf = std::sin(m.rotation);
      const glm::vec2 t = frame_.translation;
      frame_.translation = m.scale * glm::vec2(cf * t.x - sf * t.y, sf * t.x + cf * t.y) + m.translation;
      frame_.rotation = std::remainder(frame_.rotation + m.rotation, 6.2831853f);
      frame_.scale *= m.scale;
      // Keep the scale where floats are exact enough; its octave is what the shader wraps.
      if (!(frame_.scale > 1e-6f && frame_.scale < 1e6f) || !std::isfinite(frame_.translation.x + frame_.translation.y)) frame_ = {};
    }
    // Fewer than 3: the object left the view; the frame stays as it is.
  }
  previous_ = now;
  havePrevious_ = true;
  fit_.ms = msSince(t0);
  return fit_;
}

}  // namespace npr
