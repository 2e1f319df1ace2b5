// Anchored patterns: the per-frame similarity fit (see pattern_tracker.h).
#include "renderer/patterns/pattern_tracker.h"

#include <chrono>
#include <cmath>
#include <random>

#include "renderer/core/elapsed.h"

namespace npr {

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

const PatternFit& PatternTracker::update(const CameraMatrices& camera, const glm::ivec4& viewport, bool followRotation) {
  const auto t0 = std::chrono::steady_clock::now();
  fit_ = {};
  const std::size_t n = samples_.size();
  std::vector<glm::vec2> current(n);
  std::vector<char> visible(n, 0);
  const glm::mat4 mvp = camera.projection * camera.view;
  const glm::mat4 toObject = glm::inverse(camera.view);
  const glm::vec3 eye = glm::vec3(toObject[3]);
  for (std::size_t i = 0; i < n; ++i) {
    const Sample& s = samples_[i];
    const glm::vec4 c = mvp * glm::vec4(s.position, 1.0f);
    if (!(c.w > 1e-6f)) continue;
    const glm::vec3 ndc = glm::vec3(c) / c.w;
    if (std::fabs(ndc.x) > 1.0f || std::fabs(ndc.y) > 1.0f || std::fabs(ndc.z) > 1.0f) continue;
    // Front-facing (the far side of a closed model is hidden and moves with more parallax);
    // occlusion by other parts is not tested.
    current[i] = glm::vec2(viewport.x, viewport.y) + (glm::vec2(ndc) * 0.5f + 0.5f) * glm::vec2(viewport.z, viewport.w);
    visible[i] = glm::dot(s.normal, glm::normalize(eye - s.position)) > 0.05f;
  }
  std::vector<glm::vec2> from, to;
  std::vector<float> weights;
  if (havePrevious_) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!visible[i] || !previousVisible_[i]) continue;
      from.push_back(previous_[i]);
      to.push_back(current[i]);
      // Weighted by the pixels it stands for: its area, foreshortened (n.v), over distance squared.
      const glm::vec3 toEye = eye - samples_[i].position;
      const float d2 = glm::dot(toEye, toEye);
      const float nv = glm::dot(samples_[i].normal, toEye) / std::sqrt(std::max(d2, 1e-24f));
      weights.push_back(samples_[i].area * nv / std::max(d2, 1e-12f));
    }
  }
  fit_.samplesUsed = static_cast<int>(from.size());
  if (!havePrevious_ || from.size() < 3) {
    // Nothing to follow (first frame, or the object left the view): keep the frame as it is.
    fit_.reset = !havePrevious_;
  } else {
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
  previous_ = std::move(current);
  previousVisible_ = std::move(visible);
  havePrevious_ = true;
  fit_.ms = msSince(t0);
  return fit_;
}

}  // namespace npr
