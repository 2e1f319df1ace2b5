// Feature-line drawing (see line_pass.h).
#include "renderer/lines/line_pass.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>

#include "renderer/core/elapsed.h"
#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture_units.h"
#include "renderer/lighting/lighting_model.h"
#include "renderer/lighting/lighting_uniforms.h"

namespace npr {
namespace {

// How a buffer of ChainedLines reaches lines.vert: one row per input (its location), read once
// per instance (per segment). Integer types are read as integers.
struct LineStream {
  GLuint location;
  GLint components;
  GLenum type;
  std::size_t offset;
};
constexpr std::size_t kAttributes = offsetof(ChainedLine, attributes);
const LineStream kLineStreams[] = {
    {0, 3, GL_FLOAT, offsetof(ChainedLine, a)},
    {1, 3, GL_FLOAT, offsetof(ChainedLine, b)},
    {2, 1, GL_FLOAT, offsetof(ChainedLine, kind)},
    {3, 2, GL_FLOAT, offsetof(ChainedLine, param)},
    {4, 2, GL_FLOAT, offsetof(ChainedLine, arc)},
    {5, 1, GL_FLOAT, offsetof(ChainedLine, length)},
    {6, 2, GL_UNSIGNED_SHORT, kAttributes + offsetof(LineAttributes, materials)},
    {7, 2, GL_FLOAT, kAttributes + offsetof(LineAttributes, curvature)},
    {8, 1, GL_FLOAT, kAttributes + offsetof(LineAttributes, ink)},
    {9, 3, GL_FLOAT, kAttributes + offsetof(LineAttributes, normal)},
    {10, 4, GL_FLOAT, offsetof(ChainedLine, before)},
    {11, 4, GL_FLOAT, offsetof(ChainedLine, after)},
};
// Object units a screen pixel spans at the lines' origin (the object's centre).
float centrePixel(const CameraMatrices& placed, const glm::ivec4& viewport) {
  const float pixel = 2.0f / (placed.projection[1][1] * float(std::max(viewport.w, 1)));
  const bool perspective = placed.projection[3][3] == 0.0f;
  return perspective ? pixel * glm::length(glm::vec3(glm::inverse(placed.view) * glm::vec4(0, 0, 0, 1))) : pixel;
}
}  // namespace

void LinePass::setMesh(const Mesh* mesh) {
  mesh_ = mesh;
  edges_.reset();
  // Vertices of consecutive views' strokes this near are the same place on the surface.
  const float tolerance = mesh ? 1e-3f * mesh->radius : 0.0f;
  for (LineChains* c : {&staticChains_, &silhouetteChains_, &suggestiveChains_}) c->reset(tolerance);
  uploadedCreaseAngle_ = -1.0f;
  silhouetteEye_ = suggestiveEye_ = glm::vec3(NAN);
  suggestive_.reset();
  staticCount_ = creaseCount_ = silhouetteCount_ = suggestiveCount_ = marksCount_ = 0;
}

void LinePass::geometryChanged() {
  if (edges_ && mesh_) edges_->updatePositions(*mesh_);
  if (suggestive_) suggestive_->geometryChanged();
  uploadedCreaseAngle_ = -1.0f;
  silhouetteEye_ = suggestiveEye_ = glm::vec3(NAN);
}

bool LinePass::needsEdges(const LineSettings& ls) const { return mesh_ && !edges_ && (ls.drawnKinds() & 15u) && ls.edgeKinds(); }

void LinePass::buildEdges() {
  if (mesh_ && !edges_) edges_ = std::make_unique<FeatureEdges>(*mesh_);
}

void LinePass::update(const CameraMatrices& camera, const LineSettings& ls, const glm::ivec4& viewport, FrameStats& stats) {
  if (!ls.edgeKinds() || !mesh_) return;
  const auto t0 = std::chrono::steady_clock::now();
  const std::uint8_t kinds = ls.drawnKinds();
  if (!edges_ && (kinds & 15u)) {
    edges_ = std::make_unique<FeatureEdges>(*mesh_);
    ++stats.meshCachesBuilt;
  }
  // A set widening lines by curvature: the surface's, estimated once per mesh, then carried by
  // every line found (the rest pose's on a deforming mesh, as the other attached data).
  if (edges_ && !edges_->hasCurvature() && std::any_of(ls.sets.begin(), ls.sets.end(), [](const LineSet& s) { return s.curvature != 0.0f; })) {
    edges_->estimateCurvature(*mesh_);
    ++stats.meshCachesBuilt;
    uploadedCreaseAngle_ = -1.0f;
    silhouetteEye_ = glm::vec3(NAN);
  }
  ensureBuffers();
  if ((kinds & 14u) && uploadedCreaseAngle_ != ls.creaseAngle) {
    // Static lines are creases, then boundaries, then material boundaries: the parts asked for
    // are drawn as ranges.
    const auto& lines = edges_->staticLines(ls.creaseAngle);
    const auto& chained = staticChains_.update(lines);
    gl::uploadBuffer(staticLines_, chained.data(), chained.size() * sizeof(ChainedLine), GL_STATIC_DRAW);
    staticCount_ = lines.size();
    const auto count = [&](EdgeKind k) {
      return static_cast<std::size_t>(std::count_if(lines.begin(), lines.end(), [k](const FeatureLine& l) { return l.kind == float(k); }));
    };
    creaseCount_ = count(EdgeKind::Crease);
    boundaryCount_ = count(EdgeKind::Boundary);
    uploadedCreaseAngle_ = ls.creaseAngle;
    ++stats.bufferUploads;
  }
  const glm::vec3 eye = glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 0, 0, 1));
  if ((kinds & 1u) && !(eye == silhouetteEye_)) {
    const auto& lines = silhouetteChains_.update(edges_->silhouettes(eye), 2.0f * centrePixel(camera, viewport));
    gl::uploadBuffer(silhouettes_, lines.data(), lines.size() * sizeof(ChainedLine), GL_STREAM_DRAW);
    silhouetteCount_ = lines.size();
    silhouetteEye_ = eye;
    ++stats.bufferUploads;
  }
  if ((kinds & 32u) && (!(eye == suggestiveEye_) || suggestiveThreshold_ != ls.suggestiveThreshold)) {
    if (!suggestive_) {
      suggestive_ = std::make_unique<SuggestiveContours>(*mesh_);
      ++stats.meshCachesBuilt;
    }
    const auto& lines = suggestiveChains_.update(suggestive_->lines(eye, ls.suggestiveThreshold), 2.0f * centrePixel(camera, viewport));
    gl::uploadBuffer(suggestiveLines_, lines.data(), lines.size() * sizeof(ChainedLine), GL_STREAM_DRAW);
    suggestiveCount_ = lines.size();
    suggestiveEye_ = eye;
    suggestiveThreshold_ = ls.suggestiveThreshold;
    ++stats.bufferUploads;
  }
  stats.cpuLinesMs += msSince(t0);
}

Status LinePass::drawStyle(LineStyle style, const CameraMatrices& camera, const glm::ivec4& viewport, gl::ProgramCache& programs, FrameStats& stats) {
  if (!mesh_ || !vao_) return okStatus();
  if (style.byMaterial()) style.resolveMaterials(mesh_->materials);
  if (edges_) style.curvatureReference = edges_->medianCurvature();
  {
    std::vector<LineRange> ranges;
    if (style.kinds & 1u) ranges.push_back({&silhouettes_, 0, silhouetteCount_});
    if (style.kinds & 2u) ranges.push_back({&staticLines_, 0, creaseCount_});
    if (style.kinds & 4u) ranges.push_back({&staticLines_, creaseCount_, boundaryCount_});
    if (style.kinds & 8u) ranges.push_back({&staticLines_, creaseCount_ + boundaryCount_, staticCount_ - creaseCount_ - boundaryCount_});
    if (style.kinds & 32u) ranges.push_back({&suggestiveLines_, 0, suggestiveCount_});
    if (ranges.empty()) return okStatus();
    return drawLineRanges(ranges, camera, style, viewport, vao_, programs, stats);
  }
}

LineStyle LineStyle::base(const LineSettings& ls, const std::string* object) {
  LineStyle s;
  s.width = ls.width;
  static_assert(kLineKindCount == kEdgeKinds, "a row of kLineKinds per EdgeKind");
  for (int k = 0; k < kEdgeKinds; ++k) s.colours[k] = ls.*kLineKinds[k].colour;
  s.hidden = ls.hidden;
  s.hiddenWidthScale = 0.6f;
  s.hiddenInk = 0.6f;
  s.sketchy = ls.sketchy;
  s.falloff = ls.depthFalloff;
  s.kinds = ls.baseKinds(object);
  return s;
}

LineStyle LineStyle::of(const LineSet& set, const LineSettings& ls) {
  LineStyle s = base(ls, nullptr);
  s.width = set.width;
  if (set.colour) std::fill(std::begin(s.colours), std::end(s.colours), *set.colour);
  s.visible = set.visibility != LineSet::Visibility::Hidden;
  s.hidden = set.visibility != LineSet::Visibility::Visible;
  s.dash = set.dash;
  if (set.dash.x > 0.0f) s.hiddenDash = set.dash;
  s.hiddenWidthScale = s.hiddenInk = 1.0f;  // the set says how its hidden lines look
  s.sketchy = set.sketchy;
  s.falloff = set.falloff;
  s.taper = set.taper;
  s.texture = set.texture;
  s.toneColour = set.toneColour;
  s.curvatureGain = set.curvature;
  s.occlusion = set.occlusion;
  s.kinds = set.kinds;
  if (!set.materials.empty()) s.materialNames = &set.materials;
  return s;
}

void LineStyle::resolveMaterials(const std::vector<MeshMaterial>& materials) {
  materialMask.fill(0u);
  if (!materialNames) return;
  LineSet names;
  names.materials = *materialNames;
  for (std::size_t i = 0; i < materials.size() && i < std::size_t(kMaxSelectableMaterials); ++i)
    if (names.takesMaterial(materials[i].name)) materialMask[i / 32] |= 1u << (i % 32);
}

std::optional<LineStyle> lineStyleLayer(const LineSettings& ls, int layer, const std::string* object) {
  if (layer < 0) return ls.baseKinds(object) ? std::optional(LineStyle::base(ls, object)) : std::nullopt;
  const LineSet& set = ls.sets[std::size_t(layer)];
  return set.appliesTo(object) ? std::optional(LineStyle::of(set, ls)) : std::nullopt;
}

std::vector<LineStyle> lineStyles(const LineSettings& ls, const std::string* object) {
  std::vector<LineStyle> out;
  for (int layer = -1; layer < int(ls.sets.size()); ++layer)
    if (std::optional<LineStyle> style = lineStyleLayer(ls, layer, object)) out.push_back(*style);
  return out;
}

Status drawLineRanges(const std::vector<LineRange>& ranges, const CameraMatrices& placed, const LineStyle& style, const glm::ivec4& viewport,
                      const gl::VertexArray& vao, gl::ProgramCache& programs, FrameStats& stats) {
  const glm::vec3 eye = glm::vec3(glm::inverse(placed.view) * glm::vec4(0, 0, 0, 1));
  // The visible parts, then the hidden ones where the surface is in front of them.
  for (const bool hidden : {false, true}) {
    if (!(hidden ? style.hidden : style.visible)) continue;
    const bool sketchy = style.sketchy && !hidden;
    const glm::vec2 dash = hidden ? style.hiddenDash : style.dash;
    const bool tapered = style.taper > 0.0f && !hidden;
    const bool textured = style.textureBound.id != 0 && !hidden;
    const bool byCurvature = style.curvatureGain != 0.0f;
    gl::LineProgram variant{sketchy, style.falloff, dash.x > 0.0f, tapered, style.byMaterial(), textured, byCurvature};
    variant.occlusionLimit = hidden && style.limitsOcclusion();
    if (style.tonedNow()) {
      variant.lighting = style.lighting->features();
      variant.palette = style.palette->matchingVariant(style.match);
    }
    Result<gl::ShaderProgram*> prog = programs.get(variant, stats.shaderBuilds);
    if (!prog) return Error{prog.error()};
    gl::ShaderProgram& p = **prog;
    if (textured) {
      glScissor(viewport.x, viewport.y, viewport.z, viewport.w);
      gl::apply(gl::pass::kClearViewport);
      glClearStencil(0);
      glClear(GL_STENCIL_BUFFER_BIT);
    }
    gl::apply(hidden ? gl::pass::kHiddenLines : textured ? gl::pass::kTexturedLines : gl::pass::kLines);
    p.use();
    p.set("uModelViewProjection", placed.projection * placed.view);
    p.set("uViewport", glm::vec2(viewport.z, viewport.w));
    const float width = std::max(hidden ? style.hiddenWidthScale * style.width : style.width, 0.5f);
    p.set("uWidth", width);
    p.setArray("uColours", style.colours, kEdgeKinds);
    p.set("uFalloffDepth", glm::length(eye));
    p.set("uInk", hidden ? style.hiddenInk : 1.0f);
    if (dash.x > 0.0f) p.set("uDash", dash);
    // Intersection lines: pulled by about a surface's rise over the quad's half width at 60
    // degrees of slope, twice over (lines.vert).
    const bool perspective = placed.projection[3][3] == 0.0f;
    const float pixel = 2.0f / (placed.projection[1][1] * float(std::max(viewport.w, 1)));
    p.set("uValleyPixels", 2.0f * (0.5f * width + 1.0f) * 1.8f);
    p.set("uEye", perspective ? glm::vec4(eye, 1.0f) : glm::vec4(glm::normalize(glm::vec3(glm::inverse(placed.view) * glm::vec4(0, 0, 1, 0))), 0.0f));
    p.set("uPixelScale", perspective ? glm::vec2(pixel, 0.0f) : glm::vec2(0.0f, pixel));
    // Dashes and tapers in pixels at the lines' origin (the object's centre): constant along a
    // stroke, and unchanged as the view turns about it.
    p.set("uParamPixels", 1.0f / std::max(centrePixel(placed, viewport), 1e-9f));
    if (tapered) p.set("uTaper", style.taper);
    if (variant.occlusionLimit) {
      gl::bindTexture(kOcclusionLimitUnit, GL_TEXTURE_2D, style.layers->limit(style.occlusion));
      p.set("uOcclusionLimit", gl::unitIndex(kOcclusionLimitUnit));
      p.set("uOcclusionSize", glm::ivec2(viewport.z, viewport.w));
      p.set("uDepthMap", depthDistanceMap(placed.projection));
      p.set("uOcclusionTolerance", style.layers->tolerance());
    }
    if (variant.lighting) {
      // Lit in eye space as the strokes are (strokes.vert): the lines' space to the eye's.
      p.set("uModelView", placed.view);
      p.set("uNormalMatrix", glm::transpose(glm::inverse(glm::mat3(placed.view))));
      uploadLightingUniforms(p, prepareLighting<float>(*style.lighting));
      style.palette->bindMatching(p);
      const std::vector<glm::vec3>& averages = style.palette->averages();
      p.setArray("uEntryColour", averages.data(), int(averages.size()));
    }
    if (byCurvature) {
      p.set("uCurvatureGain", style.curvatureGain);
      p.set("uCurvatureReference", style.curvatureReference);
    }
    if (textured) {
      gl::bindTexture(kLineTextureUnit, GL_TEXTURE_2D, style.textureBound.id);
      p.set("uStrokeTexture", gl::unitIndex(kLineTextureUnit));
    }
    if (style.byMaterial())
      p.setArray("uMaterialMask", style.materialMask.data(), int(style.materialMask.size()));
    glBindVertexArray(vao.id());
    // Sketchy lines draw each edge three times, jittered differently in the shader.
    const int repeat = sketchy ? 3 : 1;
    for (const LineRange& r : ranges) {
      if (r.count == 0) continue;
      glBindBuffer(GL_ARRAY_BUFFER, r.buffer->id());
      const auto base = static_cast<std::uintptr_t>(r.first * sizeof(ChainedLine));
      for (const LineStream& in : kLineStreams) {
        glEnableVertexAttribArray(in.location);
        const auto at = reinterpret_cast<void*>(base + in.offset);
        if (in.type == GL_FLOAT) glVertexAttribPointer(in.location, in.components, in.type, GL_FALSE, sizeof(ChainedLine), at);
        else glVertexAttribIPointer(in.location, in.components, in.type, sizeof(ChainedLine), at);
        glVertexAttribDivisor(in.location, GLuint(repeat));
      }
      glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(r.count) * repeat);
      stats.lines += static_cast<int>(r.count);
      ++stats.drawCalls;
    }
  }
  return okStatus();
}

void LinePass::ensureBuffers() {
  if (vao_) return;
  vao_ = gl::createVertexArray();
  staticLines_ = gl::createBuffer();
  silhouettes_ = gl::createBuffer();
  suggestiveLines_ = gl::createBuffer();
  marks_ = gl::createBuffer();
}

Status LinePass::drawMarks(LineStyle style, const CameraMatrices& camera, const glm::ivec4& viewport, gl::ProgramCache& programs,
                           FrameStats& stats) {
  if (!mesh_ || !mesh_->hasMarks()) return okStatus();
  ensureBuffers();
  if (marksCount_ == 0) {
    std::vector<FeatureLine> segments;
    segments.reserve(mesh_->segments.size() / 2);
    const float kind = float(EdgeKind::Silhouette);  // drawn in the ink of the outlines
    for (std::size_t i = 0; i + 1 < mesh_->segments.size(); i += 2) segments.push_back({mesh_->segments[i], mesh_->segments[i + 1], kind});
    LineChains chains(1e-3f * mesh_->radius, false);
    std::vector<ChainedLine> all = chains.update(segments);
    // A dot is a segment of no length, with no neighbours (lines.vert draws it round).
    for (const glm::vec3& p : mesh_->dots) all.push_back({p, p, kind, glm::vec2(0.0f), glm::vec2(0.0f), 0.0f, LineAttributes{}});
    gl::uploadBuffer(marks_, all.data(), all.size() * sizeof(ChainedLine), GL_STATIC_DRAW);
    marksCount_ = all.size();
    ++stats.bufferUploads;
  }
  style.hidden = false;
  style.visible = true;
  return drawLineRanges({{&marks_, 0, marksCount_}}, camera, style, viewport, vao_, programs, stats);
}

std::vector<FeatureLine> LinePass::lines(const CameraMatrices& camera, const LineSettings& ls) {
  std::vector<FeatureLine> out;
  if (!mesh_ || !ls.edgeKinds()) return out;
  const std::uint8_t kinds = ls.drawnKinds();
  if (!edges_ && (kinds & 15u)) edges_ = std::make_unique<FeatureEdges>(*mesh_);
  if (kinds & 1u) {
    const glm::vec3 eye = glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 0, 0, 1));
    const auto& s = edges_->silhouettes(eye);
    out.insert(out.end(), s.begin(), s.end());
    silhouetteEye_ = glm::vec3(NAN);  // the uploaded silhouettes may be another eye's now
  }
  if (kinds & 32u) {
    if (!suggestive_) suggestive_ = std::make_unique<SuggestiveContours>(*mesh_);
    const glm::vec3 eye = glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 0, 0, 1));
    const auto& s = suggestive_->lines(eye, ls.suggestiveThreshold);
    out.insert(out.end(), s.begin(), s.end());
    suggestiveEye_ = glm::vec3(NAN);
  }
  if (kinds & 14u)
    for (const FeatureLine& l : edges_->staticLines(ls.creaseAngle)) {
      if ((kinds >> int(l.kind + 0.5f)) & 1u) out.push_back(l);
    }
  return out;
}

}  // namespace npr
