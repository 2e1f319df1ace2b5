// Variants to files and #define lines (see program_variants.h). The define names are the
// ones the GLSL files test; the lighting defines come from LightingFeatures::glslDefines.
#include "renderer/programs/program_variants.h"

namespace npr::gl {
namespace {

const char* patternDefine(PatternMapping m) {
  return m == PatternMapping::Anchored ? "PATTERN_ANCHORED" : m == PatternMapping::Object ? "PATTERN_OBJECT" : "PATTERN_SCALED";
}

std::vector<std::string> paletteDefines(const PaletteVariant& p) {
  std::vector<std::string> d;
  d.push_back("PALETTE_SIZE " + std::to_string(p.size));
  if (p.layerSizesDiffer) d.push_back("LAYER_SIZES_DIFFER");
  if (p.precomposited) d.push_back("PALETTE_PRECOMPOSITED");
  if (p.rows > 1 && p.axis != PaletteAxisKind::None) {
    d.push_back("PALETTE_AXIS");
    d.push_back(p.axis == PaletteAxisKind::Depth ? "AXIS_DEPTH" : p.axis == PaletteAxisKind::Facing ? "AXIS_FACING" : "AXIS_DETAIL");
    d.push_back("PALETTE_ROWS " + std::to_string(p.rows));
    d.push_back("PALETTE_COLUMNS " + std::to_string(p.columns));
  }
  if (p.toneThreshold) d.push_back("TONE_THRESHOLD");
  else if (p.backgroundImage) d.push_back("BACKGROUND_IMAGE");
  d.push_back(p.match == MatchMode::Colors ? "MATCH_COLORS" : p.match == MatchMode::Intensity ? "MATCH_INTENSITY" : "MATCH_ORDER");
  if (p.pattern != PatternMapping::Screen) d.push_back(patternDefine(p.pattern));
  if (p.filtered) d.push_back("PATTERN_FILTERED");
  if (p.patternRest && p.pattern == PatternMapping::Object) d.push_back("PATTERN_REST");
  if (p.patternPerVertex && mapsScreenPosition(p.pattern)) d.push_back("PATTERN_FROM_VERTEX");
  if (p.orientBins > 0) {
    d.push_back("ORIENTED");
    d.push_back("ORIENT_BINS " + std::to_string(p.orientBins));
    if (p.entryAngleShared) d.push_back("ENTRY_ANGLE_SHARED");
  }
  d.push_back("LUT1D_SIZE " + std::to_string(kLut1DSize));
  d.push_back("LUT3D_SIZE " + std::to_string(kLut3DSize));
  return d;
}

std::vector<std::string> shadingDefines(MeshShading s) {
  switch (s) {
    case MeshShading::Mask: return {"PATH_MASK"};
    case MeshShading::Triangle: return {"PATH_TRIANGLE"};
    case MeshShading::Vertex: return {"PATH_VERTEX", "PER_VERTEX_LIGHTING"};
    case MeshShading::Pixel: return {"PATH_PIXEL"};
    case MeshShading::Smooth: return {"PATH_SMOOTH"};
    case MeshShading::Phong: return {"PATH_PHONG"};
    case MeshShading::Gouraud: return {"PATH_GOURAUD", "PER_VERTEX_LIGHTING"};
    case MeshShading::LitTextured: return {"PATH_LIT_TEXTURED"};
    case MeshShading::EyePosition: return {"PATH_EYE_POSITION"};
    case MeshShading::EyeNormal: return {"PATH_EYE_NORMAL"};
    case MeshShading::StrokeAngle: return {"PATH_STROKE_ANGLE"};
    case MeshShading::PatternCoordinate: return {"PATH_PATTERN_COORDINATE"};
  }
  return {};
}

struct SourceOf {
  ProgramSource operator()(const FeatureProgram& f) const { return {f.vertexFile, f.fragmentFile, f.defines}; }
  ProgramSource operator()(const MeshProgram& m) const {
    ProgramSource s{"mesh.vert", "mesh.frag", {}};
    if (m.lighting) s.defines = m.lighting->glslDefines();
    for (auto& d : shadingDefines(m.shading)) s.defines.push_back(d);
    if (m.palette) for (auto& d : paletteDefines(*m.palette)) s.defines.push_back(d);
    if (m.materials) s.defines.push_back("MATERIALS");
    if (m.alphaCoverage) s.defines.push_back("ALPHA_COVERAGE");
    const bool table = m.materials || m.alphaCoverage;
    if (table && m.materialMaps) s.defines.push_back("MATERIAL_MAPS");
    if (m.materials && m.vertexColours) s.defines.push_back("VERTEX_COLOURS");
    if (table && m.materialUniform) s.defines.push_back("MATERIAL_UNIFORM");
    if (m.output == MeshOutput::Entry) s.defines.push_back("OUTPUT_ENTRY");
    if (m.output == MeshOutput::Blend) s.defines.push_back("OUTPUT_BLEND");
    if (m.deferTurn) s.defines.push_back("DEFER_TURN");
    if (m.toneEdges) s.defines.push_back("TONE_EDGES");
    if (m.peel) s.defines.push_back("PEEL_BEHIND");
    if (m.shading == MeshShading::Mask && (m.stroke == StrokeSource::Field || m.stroke == StrokeSource::Light))
      s.defines.push_back("MASK_STROKE_ANGLE");
    if (m.shading == MeshShading::Mask && m.palette && m.palette->pattern == PatternMapping::Object)
      s.defines.push_back("MASK_PATTERN_COORDINATE");
    if (m.palette && m.palette->pattern == PatternMapping::Object &&
        (m.shading == MeshShading::Mask || m.shading == MeshShading::PatternCoordinate || m.shading == MeshShading::Triangle ||
         m.shading == MeshShading::Vertex))
      s.defines.push_back("PATTERN_FACE_NORMAL");
    if (m.stroke == StrokeSource::Field) s.defines.push_back("ORIENT_FIELD");
    if (m.stroke == StrokeSource::Light) s.defines.push_back("ORIENT_LIGHT");
    if (m.stroke == StrokeSource::Fixed) s.defines.push_back("ORIENT_FIXED");
    if (m.occlusion) s.defines.push_back("OCCLUSION");
    if (m.screenOcclusion) s.defines.push_back("SCREEN_OCCLUSION");
    if (m.groundShadowMap) s.defines.push_back("GROUND_SHADOW_MAP");
    if (m.control == MeshControl::Shadow) s.defines.push_back("CONTROL_SHADOW");
    if (m.control == MeshControl::Occlusion) s.defines.push_back("CONTROL_OCCLUSION");
    if (m.shadowLayers > 0) {
      s.defines.push_back("SHADOWS");
      s.defines.push_back("SHADOW_LAYERS " + std::to_string(m.shadowLayers));
    }
    return s;
  }
  ProgramSource operator()(const QuadProgram& q) const {
    ProgramSource s{"fullscreen.vert", "quad.frag", {}};
    s.defines.push_back(q.kind == QuadProgram::Kind::Background ? "QUAD_BACKGROUND" : "QUAD_LAYER");
    if (q.backgroundImage) s.defines.push_back("BACKGROUND_IMAGE");
    if (q.pattern != PatternMapping::Screen) s.defines.push_back(patternDefine(q.pattern));
    // Three vertices for the whole screen: interpolating the pattern's coordinate always pays.
    if (mapsScreenPosition(q.pattern)) s.defines.push_back("PATTERN_FROM_VERTEX");
    // Full-screen quads know nothing of the surface: they read the object-space pattern's
    // coordinates from the buffer the stencil path drew.
    if (q.pattern == PatternMapping::Object) s.defines.push_back("PATTERN_OBJECT_BUFFER");
    if (q.layerSizesDiffer) s.defines.push_back("LAYER_SIZES_DIFFER");
    if (q.filtered) s.defines.push_back("PATTERN_FILTERED");
    if (q.opaque) s.defines.push_back("LAYER_OPAQUE");
    if (q.orientBins > 0) {
      s.defines.push_back("ORIENTED");
      s.defines.push_back("ORIENT_BINS " + std::to_string(q.orientBins));
      if (q.orientBuffer) s.defines.push_back("ORIENT_BUFFER");
    }
    return s;
  }
  ProgramSource operator()(const LineProgram& l) const {
    ProgramSource s{"lines.vert", "lines.frag", {"EDGE_KINDS " + std::to_string(kEdgeKinds)}};
    if (l.sketchy) s.defines.push_back("SKETCHY");
    if (l.depthFalloff) s.defines.push_back("DEPTH_FALLOFF");
    if (l.dashed) s.defines.push_back("DASHED");
    if (l.tapered) s.defines.push_back("TAPERED");
    if (l.byMaterial) s.defines.push_back("BY_MATERIAL");
    if (l.textured) s.defines.push_back("TEXTURED");
    if (l.byCurvature) s.defines.push_back("BY_CURVATURE");
    if (l.occlusionLimit) s.defines.push_back("OCCLUSION_LIMIT");
    if (l.lighting && l.palette) {
      s.defines.push_back("TONE_COLOUR");
      for (auto& d : l.lighting->glslDefines()) s.defines.push_back(d);
      for (auto& d : paletteDefines(*l.palette)) s.defines.push_back(d);
    }
    return s;
  }
  ProgramSource operator()(const OutlineProgram& o) const {
    // The offset method needs no geometry stage: the rasterizer culls the front faces.
    const bool offset = !o.rim() && o.method == OutlineMethod::Offset;
    ProgramSource s{"outline.vert", "outline.frag", {}, offset ? "" : "outline.geom"};
    if (o.rim()) {
      s.defines.push_back("OUTLINE_RIM");
      for (auto& d : paletteDefines(*o.palette)) s.defines.push_back(d);
      return s;
    }
    switch (o.method) {
      case OutlineMethod::Edges: s.defines.push_back("OUTLINE_EDGES"); break;
      case OutlineMethod::Offset: s.defines.push_back("OUTLINE_OFFSET"); break;
      case OutlineMethod::Fatten: s.defines.push_back("OUTLINE_FATTEN"); break;
    }
    return s;
  }
  ProgramSource operator()(const StrokeProgram& st) const {
    ProgramSource s{"strokes.vert", "strokes.frag", st.lighting.glslDefines()};
    for (auto& d : paletteDefines(st.palette)) s.defines.push_back(d);
    return s;
  }
  ProgramSource operator()(const EdgeProgram&) const { return {"fullscreen.vert", "edges.frag", {}}; }
  ProgramSource operator()(const GroundShadowProgram& g) const {
    return {"fullscreen.vert", "ground_shadow.frag",
            {"NUM_LIGHTS " + std::to_string(g.lights), "SHADOWS", "SHADOW_LAYERS " + std::to_string(g.shadowLayers)}};
  }
  ProgramSource operator()(const TurnResolveProgram& t) const {
    ProgramSource s{"fullscreen.vert", "turn_resolve.frag", paletteDefines(t.palette)};
    if (t.blend) s.defines.push_back("RESOLVE_BLEND");
    return s;
  }
  ProgramSource operator()(const DeformProgram& d) const {
    ProgramSource s{"", "", {}};
    s.computeFile = "deform.comp";
    if (d.skin) s.defines.push_back("SKIN");
    if (d.vectors) s.defines.push_back("VECTORS");
    else if (d.morph) {
      s.defines.push_back("MORPH");
      s.defines.push_back("MAX_ACTIVE_TARGETS " + std::to_string(DeformProgram::kMaxActiveTargets));
    }
    return s;
  }
  ProgramSource operator()(const MarkerProgram&) const { return {"marker.vert", "marker.frag", {}}; }
  ProgramSource operator()(const SupersampleProgram&) const { return {"fullscreen.vert", "supersample_resolve.frag", {}}; }
  ProgramSource operator()(const EdgeFilterProgram&) const { return {"fullscreen.vert", "edge_filter.frag", {}}; }
  ProgramSource operator()(const ShadowDepthProgram& d) const {
    ProgramSource s{"shadow_depth.vert", "shadow_depth.frag", {}};
    if (d.alphaCoverage) s.defines.push_back("ALPHA_COVERAGE");
    if (d.alphaCoverage && d.materialMaps) s.defines.push_back("MATERIAL_MAPS");
    return s;
  }
  ProgramSource operator()(const OcclusionBakeProgram&) const { return {"occlusion_bake.vert", "occlusion_bake.frag", {}}; }
  ProgramSource operator()(const TriangleLightProgram& t) const {
    ProgramSource s{"triangle_light.vert", "triangle_light.frag", t.lighting.glslDefines()};
    for (auto& d : paletteDefines(t.palette)) s.defines.push_back(d);
    if (t.occlusion) s.defines.push_back("OCCLUSION");
    if (t.shadowLayers > 0) {
      s.defines.push_back("SHADOWS");
      s.defines.push_back("SHADOW_LAYERS " + std::to_string(t.shadowLayers));
    }
    return s;
  }
};

}  // namespace

ProgramSource programSource(const ProgramVariant& variant) { return std::visit(SourceOf{}, variant); }

}  // namespace npr::gl
