// Vector export of the feature lines (see svg_export.h).
#include "renderer/lines/svg_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "renderer/lines/line_chains.h"

namespace npr {
namespace {

// Whether eye-space point p (on the surface or its outline) is hidden at pixel (x, y): hidden
// only if every pixel of the 3x3 block around it has a surface clearly in front, so lines on
// the outline (where the depth jumps) and on the surface itself stay.
bool hidden(const ImageRGBA32F& eye, int x, int y, const glm::vec3& p) {
  const float tolerance = 0.004f * std::fabs(p.z) + 0.004f;  // eye units: the model fits a unit sphere
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int xx = x + dx, yy = y + dy;
      if (xx < 0 || yy < 0 || xx >= eye.width || yy >= eye.height) return false;
      const float* e = &eye.pixels[(std::size_t(yy) * std::size_t(eye.width) + std::size_t(xx)) * 4];
      if (e[3] < 0.5f) return false;                 // no surface there
      if (e[2] <= p.z + tolerance) return false;     // the surface is not in front (eye z is negative)
    }
  return true;
}

struct Projector {
  const CameraMatrices& camera;
  glm::vec2 size;
  glm::vec2 window(const glm::vec3& eye) const {
    const glm::vec4 c = camera.projection * glm::vec4(eye, 1.0f);
    const glm::vec2 ndc = glm::vec2(c) / c.w;
    return {(ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y};
  }
};

// Joins segments that share an end (to a 1/1000 pixel) into chains (line_chains.h), in drawing
// order: chains start at free ends and junctions; what is left are closed loops.
std::vector<std::vector<glm::vec2>> chain(const std::vector<std::pair<glm::vec2, glm::vec2>>& segments) {
  auto key = [](glm::vec2 p) { return ChainKey{std::llround(p.x * 1000.0), std::llround(p.y * 1000.0), 0}; };
  std::vector<ChainKey> ends;
  ends.reserve(2 * segments.size());
  for (const auto& [a, b] : segments) {
    ends.push_back(key(a));
    ends.push_back(key(b));
  }
  std::vector<std::vector<glm::vec2>> chains;
  for (const std::vector<ChainStep>& steps : chainSegments(ends)) {
    std::vector<glm::vec2> c;
    const auto& first = segments[steps.front().segment];
    c.push_back(steps.front().reversed ? first.second : first.first);
    for (const ChainStep& s : steps) c.push_back(s.reversed ? segments[s.segment].first : segments[s.segment].second);
    chains.push_back(std::move(c));
  }
  return chains;
}

}  // namespace

SvgLines visibleLineChains(const std::vector<FeatureLine>& lines, const CameraMatrices& camera, const glm::ivec2& size,
                           const ImageRGBA32F& eyePosition, bool hiddenParts) {
  const Projector proj{camera, glm::vec2(size)};
  const float nearZ = -1e-4f;  // clip just in front of the eye; the projection's near plane clips the rest
  std::vector<std::pair<glm::vec2, glm::vec2>> segments[kEdgeKinds];
  for (const FeatureLine& l : lines) {
    glm::vec3 a = glm::vec3(camera.view * glm::vec4(l.a, 1.0f)), b = glm::vec3(camera.view * glm::vec4(l.b, 1.0f));
    if (a.z > nearZ && b.z > nearZ) continue;  // behind the eye
    if (a.z > nearZ) a = glm::mix(b, a, (b.z - nearZ) / (b.z - a.z));
    if (b.z > nearZ) b = glm::mix(a, b, (a.z - nearZ) / (a.z - b.z));
    const glm::vec2 wa = proj.window(a), wb = proj.window(b);
    if (!std::isfinite(wa.x + wa.y + wb.x + wb.y)) continue;
    // Sampled at about a pixel's step along the screen; runs of visible samples are kept.
    const int steps = std::clamp(int(std::ceil(glm::length(wb - wa))), 1, 100000);
    const int kind = std::clamp(int(l.kind + 0.5f), 0, kEdgeKinds - 1);
    int runStart = -1;
    glm::vec2 previous{0.0f};
    for (int i = 0; i <= steps + 1; ++i) {
      bool visible = false;
      glm::vec2 w{0.0f};
      if (i <= steps) {
        // Perspective-correct: the eye point whose projection lies a fraction t along the screen segment.
        const float t = float(i) / float(steps);
        const float s = (t / b.z) / ((1.0f - t) / a.z + t / b.z);
        const glm::vec3 p = glm::mix(a, b, s);
        w = glm::mix(wa, wb, t);
        const int x = int(std::floor(w.x)), y = int(std::floor(w.y));
        visible = x >= 0 && y >= 0 && x < size.x && y < size.y && hidden(eyePosition, x, y, p) == hiddenParts;
      }
      if (visible && runStart < 0) {
        runStart = i;
        previous = w;
      }
      if (!visible && runStart >= 0) {
        const glm::vec2 from = runStart == 0 ? wa : previous, to = i - 1 == steps ? wb : glm::mix(wa, wb, float(i - 1) / float(steps));
        if (glm::length(to - from) > 0.0f) segments[kind].emplace_back(from, to);
        runStart = -1;
      }
    }
  }
  SvgLines out;
  for (int k = 0; k < kEdgeKinds; ++k) {
    out.chains[k] = chain(segments[k]);
    for (const auto& c : out.chains[k]) {
      ++out.paths;
      for (std::size_t i = 1; i < c.size(); ++i) out.lengthPx += glm::length(c[i] - c[i - 1]);
    }
  }
  return out;
}

std::vector<glm::vec2> visibleDots(const std::vector<glm::vec3>& dots, const CameraMatrices& camera, const glm::ivec2& size,
                                   const ImageRGBA32F& eyePosition) {
  const Projector proj{camera, glm::vec2(size)};
  std::vector<glm::vec2> out;
  for (const glm::vec3& d : dots) {
    const glm::vec3 p = glm::vec3(camera.view * glm::vec4(d, 1.0f));
    if (p.z > -1e-4f) continue;  // at or behind the eye
    const glm::vec2 w = proj.window(p);
    if (!std::isfinite(w.x + w.y)) continue;
    const float x = std::floor(w.x), y = std::floor(w.y);
    if (x < 0.0f || y < 0.0f || x >= float(size.x) || y >= float(size.y)) continue;
    if (!hidden(eyePosition, int(x), int(y), p)) out.push_back(w);
  }
  return out;
}

std::string hexColour(const glm::vec3& c) {
  char s[8];
  auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  std::snprintf(s, sizeof s, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return s;
}

namespace {

std::string base64(const std::vector<std::uint8_t>& data) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((data.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < data.size(); i += 3) {
    const std::uint32_t v = std::uint32_t(data[i]) << 16 | (i + 1 < data.size() ? std::uint32_t(data[i + 1]) << 8 : 0u) |
                            (i + 2 < data.size() ? std::uint32_t(data[i + 2]) : 0u);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += i + 1 < data.size() ? table[(v >> 6) & 63] : '=';
    out += i + 2 < data.size() ? table[v & 63] : '=';
  }
  return out;
}

}  // namespace

std::vector<std::vector<glm::vec2>> taperedOutlines(const std::vector<glm::vec2>& chain, float width, float taper, glm::vec2 dash) {
  std::vector<std::vector<glm::vec2>> out;
  if (chain.size() < 2 || !(width > 0.0f)) return out;
  std::vector<float> arc(chain.size(), 0.0f);
  for (std::size_t i = 1; i < chain.size(); ++i) arc[i] = arc[i - 1] + glm::length(chain[i] - chain[i - 1]);
  const float length = arc.back();
  if (!(length > 0.0f)) return out;
  const bool closed = chain.size() > 2 && glm::length(chain.front() - chain.back()) < 1e-3f;
  const float ends = std::max(std::min(taper, 0.5f * length), 1e-3f);
  const auto halfWidth = [&](float s) { return closed || taper <= 0.0f ? 0.5f * width : 0.5f * width * std::clamp(std::min(s, length - s) / ends, 0.0f, 1.0f); };
  // The point and unit normal at arc length s (the normal of the segment it lies on, averaged
  // with the neighbour's at a vertex, so the outline's sides join without gaps).
  const auto normalOf = [&](std::size_t seg) {
    const glm::vec2 d = chain[seg + 1] - chain[seg];
    const float l = glm::length(d);
    return l > 0.0f ? glm::vec2(-d.y, d.x) / l : glm::vec2(0.0f);
  };
  const auto sideAt = [&](std::size_t vertex) {
    glm::vec2 n(0.0f);
    if (vertex > 0) n += normalOf(vertex - 1);
    if (vertex + 1 < chain.size()) n += normalOf(vertex);
    if (closed && (vertex == 0 || vertex + 1 == chain.size())) n = normalOf(0) + normalOf(chain.size() - 2);
    const float l = glm::length(n);
    return l > 1e-6f ? n / l : glm::vec2(0.0f);
  };
  // The pieces to outline: [from, to] in arc length (dashes, or the whole chain).
  std::vector<glm::vec2> pieces;
  if (dash.x > 0.0f) {
    for (float s = 0.0f; s < length && pieces.size() < 100000; s += dash.x + dash.y) pieces.push_back({s, std::min(s + dash.x, length)});
  } else {
    pieces.push_back({0.0f, length});
  }
  // Where the width changes: the vertices, and steps through the tapers so their outline is a
  // curve rather than a straight cut from the point to the first vertex.
  std::vector<float> marks(arc);
  if (!closed && taper > 0.0f)
    for (int k = 1; k <= 8; ++k) {
      marks.push_back(ends * float(k) / 8.0f);
      marks.push_back(length - ends * float(k) / 8.0f);
    }
  std::sort(marks.begin(), marks.end());
  for (const glm::vec2& piece : pieces) {
    std::vector<float> at{piece.x};
    for (float m : marks)
      if (m > piece.x && m < piece.y) at.push_back(m);
    at.push_back(piece.y);
    std::vector<glm::vec2> left, right;
    std::size_t seg = 0;
    for (float a : at) {
      while (seg + 2 < chain.size() && arc[seg + 1] < a) ++seg;
      const float t = arc[seg + 1] > arc[seg] ? std::clamp((a - arc[seg]) / (arc[seg + 1] - arc[seg]), 0.0f, 1.0f) : 0.0f;
      const glm::vec2 p = glm::mix(chain[seg], chain[seg + 1], t);
      // At a vertex the sides' normals are averaged, so the outline joins without gaps.
      const glm::vec2 n = t <= 0.0f ? sideAt(seg) : t >= 1.0f ? sideAt(seg + 1) : normalOf(seg);
      const float h = halfWidth(a);
      left.push_back(p + n * h);
      right.push_back(p - n * h);
    }
    std::vector<glm::vec2> polygon(left);
    polygon.insert(polygon.end(), right.rbegin(), right.rend());
    out.push_back(std::move(polygon));
  }
  return out;
}

std::vector<SvgGroup> kindGroups(const SvgLines& lines, const LineSettings& style) {
  std::vector<SvgGroup> out;
  for (int k = 0; k < kEdgeKinds; ++k)
    out.push_back({kLineKinds[k].plural, style.*kLineKinds[k].colour, style.width, 1.0f, glm::vec2(0.0f), lines.chains[k]});
  return out;
}

std::string svgDocument(const std::vector<SvgGroup>& groups, const glm::ivec2& size, const std::vector<std::uint8_t>& rasterPng,
                        const SvgFills* fills, const std::vector<SvgDots>& dots) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"" << size.x
    << "\" height=\"" << size.y << "\" viewBox=\"0 0 " << size.x << " " << size.y << "\">\n"
    << "<title>npr-viewer feature lines</title>\n";
  if (!rasterPng.empty())
    o << "<image id=\"rendering\" x=\"0\" y=\"0\" width=\"" << size.x << "\" height=\"" << size.y
      << "\" xlink:href=\"data:image/png;base64," << base64(rasterPng) << "\"/>\n";
  char number[96];
  if (fills) {
    // A GL window's pattern row 0 is its bottom row and the palette's image rows are flipped on
    // upload, so a tile drawn upright starts at y = height mod its height (see pattern.glsl).
    auto pattern = [&](const std::string& id, const SvgPattern& p) {
      const float w = float(p.size.x) * fills->scale, h = float(p.size.y) * fills->scale;
      std::snprintf(number, sizeof number, "%.3f", double(std::fmod(float(size.y), h)));
      o << "<pattern id=\"" << id << "\" patternUnits=\"userSpaceOnUse\" x=\"0\" y=\"" << number << "\" width=\"" << w << "\" height=\"" << h
        << "\"><image width=\"" << w << "\" height=\"" << h << "\" image-rendering=\"optimizeSpeed\" preserveAspectRatio=\"none\" xlink:href=\"data:image/png;base64,"
        << base64(p.png) << "\"/></pattern>\n";
    };
    o << "<defs>\n";
    if (fills->background) pattern("background", *fills->background);
    for (std::size_t e = 0; e < fills->entries.size(); ++e)
      if (e < fills->regions.size() && !fills->regions[e].empty()) pattern("entry" + std::to_string(e), fills->entries[e]);
    o << "</defs>\n<g id=\"fills\">\n<rect id=\"background\" x=\"0\" y=\"0\" width=\"" << size.x << "\" height=\"" << size.y << "\" fill=\""
      << (fills->background ? std::string("url(#background)") : hexColour(fills->backgroundColour)) << "\"/>\n";
    for (std::size_t e = 0; e < fills->entries.size() && e < fills->regions.size(); ++e) {
      if (fills->regions[e].empty()) continue;
      o << "<path id=\"region" << e << "\" fill=\"url(#entry" << e << ")\" d=\"";
      for (const auto& loop : fills->regions[e]) {
        for (std::size_t i = 0; i < loop.size(); ++i) o << (i ? "L" : "M") << loop[i].x << ' ' << loop[i].y;
        o << 'Z';
      }
      o << "\"/>\n";
    }
    o << "</g>\n";
  }
  for (const SvgGroup& g : groups) {
    if (g.chains.empty()) continue;
    if (g.taper > 0.0f) {
      // Filled outlines: one path per chain, a closed piece per dash.
      o << "<g id=\"" << g.id << "\" fill=\"" << hexColour(g.colour) << "\" stroke=\"none\"";
      if (g.opacity < 1.0f) o << " fill-opacity=\"" << g.opacity << "\"";
      o << ">\n";
      for (const auto& c : g.chains) {
        const std::vector<std::vector<glm::vec2>> pieces = taperedOutlines(c, g.width, g.taper, g.dash);
        if (pieces.empty()) continue;
        o << "<path d=\"";
        for (const auto& piece : pieces) {
          for (std::size_t i = 0; i < piece.size(); ++i) {
            std::snprintf(number, sizeof number, "%s%.2f %.2f", i ? "L" : "M", double(piece[i].x), double(piece[i].y));
            o << number;
          }
          o << 'Z';
        }
        o << "\"/>\n";
      }
      o << "</g>\n";
      continue;
    }
    o << "<g id=\"" << g.id << "\" fill=\"none\" stroke=\"" << hexColour(g.colour) << "\" stroke-width=\"" << g.width
      << "\" stroke-linecap=\"" << (g.dash.x > 0.0f ? "butt" : "round") << "\" stroke-linejoin=\"round\"";
    if (g.opacity < 1.0f) o << " stroke-opacity=\"" << g.opacity << "\"";
    if (g.dash.x > 0.0f) {
      std::snprintf(number, sizeof number, " stroke-dasharray=\"%.2f %.2f\"", double(g.dash.x), double(g.dash.y));
      o << number;
    }
    o << ">\n";
    for (const auto& c : g.chains) {
      o << "<polyline points=\"";
      for (std::size_t i = 0; i < c.size(); ++i) {
        std::snprintf(number, sizeof number, "%s%.2f,%.2f", i ? " " : "", double(c[i].x), double(c[i].y));
        o << number;
      }
      o << "\"/>\n";
    }
    o << "</g>\n";
  }
  for (const SvgDots& d : dots) {
    if (d.centres.empty()) continue;
    o << "<g id=\"" << d.id << "\" fill=\"" << hexColour(d.colour) << "\" stroke=\"none\">\n";
    for (const glm::vec2& c : d.centres) {
      std::snprintf(number, sizeof number, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\"/>\n", double(c.x), double(c.y), double(0.5f * d.diameter));
      o << number;
    }
    o << "</g>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace npr
