// The automatic tone range (see tone_range.h).
#include "renderer/palette/tone_range.h"

#include <algorithm>
#include <cmath>

#include "renderer/lighting/lighting_model.h"
#include "renderer/materials/mesh_materials.h"

namespace npr {

void sampleTones(const Mesh& mesh, const LightingState& lighting, const glm::mat4& modelView, const glm::mat4& projection,
                 bool materials, MatchMode mode, std::size_t budget, std::vector<ToneSample>& out) {
  const std::size_t nf = mesh.triangleCount();
  if (nf == 0 || budget == 0) return;
  const std::size_t stride = toneSampleStride(nf, budget);
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(modelView)));
  const glm::mat4 mvp = projection * modelView;
  const bool own = materials && mesh.hasAppearance() && mesh.faceMaterials.size() == nf;
  std::vector<PreparedLighting<float>> prepared;
  if (own) {
    for (const Material& m : glMaterials(mesh, lighting)) prepared.push_back(prepareLighting<float>(lighting.withMaterial(m)));
  } else {
    prepared.push_back(prepareLighting<float>(lighting));
  }
  const bool tints = materials && mesh.faceTints.size() == nf;
  const bool colours = materials && mesh.colours.size() == mesh.positions.size();
  for (std::size_t f = stride / 2; f < nf; f += stride) {
    const std::uint32_t* v = &mesh.indices[3 * f];
    glm::vec2 screen[3];
    bool inside = true;
    for (int k = 0; k < 3; ++k) {
      const glm::vec4 c = mvp * glm::vec4(mesh.positions[v[k]], 1.0f);
      if (!(c.w > 1e-6f)) {
        inside = false;
        break;
      }
      screen[k] = glm::vec2(c) / c.w;
    }
    if (!inside) continue;
    // Front-facing (counter-clockwise on screen) and on screen, by its area there.
    const float area = 0.5f * ((screen[1].x - screen[0].x) * (screen[2].y - screen[0].y) - (screen[2].x - screen[0].x) * (screen[1].y - screen[0].y));
    const glm::vec2 lo = glm::min(screen[0], glm::min(screen[1], screen[2])), hi = glm::max(screen[0], glm::max(screen[1], screen[2]));
    if (!(area > 0.0f) || hi.x < -1.0f || lo.x > 1.0f || hi.y < -1.0f || lo.y > 1.0f) continue;
    const glm::vec3 pos(modelView * glm::vec4(mesh.faceCentroids[f], 1.0f));
    const glm::vec3 n = normalMatrix * mesh.faceNormals[f];
    glm::vec3 scale(1.0f);
    if (tints) scale *= mesh.faceTints[f];
    if (colours) scale *= (mesh.colours[v[0]] + mesh.colours[v[1]] + mesh.colours[v[2]]) / 3.0f;
    const PreparedLighting<float>& p = prepared[own ? std::min<std::size_t>(mesh.faceMaterials[f], prepared.size() - 1) : 0];
    const glm::vec3 c = shade(p, pos, n, false, scale);
    const float q = mode == MatchMode::Intensity ? 3.0f * std::max(c.r, std::max(c.g, c.b)) : c.r + c.g + c.b;
    // The triangle stands for the `stride` triangles around it.
    out.push_back({q, area * float(stride)});
  }
}

std::optional<glm::vec2> percentileRange(std::vector<ToneSample>& samples, float low, float high, float minSpan) {
  double total = 0.0;
  for (const ToneSample& s : samples) total += s.weight > 0.0f && std::isfinite(s.weight) && std::isfinite(s.query) ? s.weight : 0.0;
  if (!(total > 0.0)) return std::nullopt;
  std::sort(samples.begin(), samples.end(), [](const ToneSample& a, const ToneSample& b) { return a.query < b.query; });
  // Interpolated between neighbouring samples by where the wanted weight falls inside the
  // sample that crosses it: the percentile then moves continuously as areas change with the
  // view, instead of jumping from one sample's tone to the next (without smoothing over frames,
  // the dark object of test_gl_tone_range orbiting moved 8 quanta a frame, stepwise).
  auto at = [&](float percent) {
    const double want = total * std::clamp(percent, 0.0f, 100.0f) / 100.0;
    double sum = 0.0;
    std::optional<float> previous;
    for (const ToneSample& s : samples) {
      if (!(s.weight > 0.0f) || !std::isfinite(s.weight) || !std::isfinite(s.query)) continue;
      if (sum + s.weight >= want) {
        if (!previous) return s.query;
        const float t = float(std::clamp((want - sum) / s.weight, 0.0, 1.0));
        return *previous + (s.query - *previous) * t;
      }
      sum += s.weight;
      previous = s.query;
    }
    return previous ? *previous : samples.back().query;
  };
  glm::vec2 r(at(low), at(high));
  if (r.y - r.x < minSpan) {
    const float mid = 0.5f * (r.x + r.y);
    r = glm::vec2(mid - 0.5f * minSpan, mid + 0.5f * minSpan);
  }
  return r;
}

std::optional<glm::vec2> ToneRangeTracker::update(std::optional<glm::vec2> estimate, float rate) {
  if (estimate) {
    const float k = std::clamp(rate, 0.0f, 1.0f);
    smoothed_ = smoothed_ ? *smoothed_ + (*estimate - *smoothed_) * k : *estimate;
  }
  if (!smoothed_) return std::nullopt;
  glm::vec2 q = glm::round(*smoothed_ / kStep) * kStep;
  if (!(q.y > q.x)) q.y = q.x + kStep;
  quantised_ = q;
  return quantised_;
}

}  // namespace npr
