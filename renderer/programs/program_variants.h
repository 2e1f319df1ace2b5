// Every shader program the renderer builds, as typed variants (after Magnum's shader Flags):
// one struct per program family, whose fields are the features it is specialised for. Each
// variant turns itself into its files and #define lines in one place (program_variants.cpp),
// and the program cache is keyed by that source: no field list is kept by hand.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "renderer/core/palette_axis_kind.h"
#include "renderer/gl/program_source.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/programs/shader_limits.h"
#include "renderer/settings/render_settings.h"

namespace npr::gl {

// How pixels reach palette texels (pattern.glsl): one texel per pixel from the window's corner,
// through a fixed scale (--pattern-scale), through the anchored pattern's frame, or from the
// surface's object-space position (triplanar; full-screen quads read it from a buffer).
enum class PatternMapping : std::uint8_t { Screen, Scaled, Anchored, Object };
// Mappings of the screen position (a similarity): the vertex stage can hand their coordinate on.
inline bool mapsScreenPosition(PatternMapping m) { return m == PatternMapping::Scaled || m == PatternMapping::Anchored; }

// What palette.glsl is compiled for: the palette's layout and the match mode.

struct PaletteVariant {
  int size = 0;
  bool layerSizesDiffer = false;
  bool precomposited = false;    // layers stored over the background: one fetch per pixel
  bool backgroundImage = false;  // only meaningful when not precomposited
  MatchMode match = MatchMode::Intensity;
  PatternMapping pattern = PatternMapping::Screen;
  bool filtered = false;         // mapped patterns filtered bilinearly in linear light (pattern.glsl)
  int orientBins = 0;            // lookups turned along the stroke angle in this many steps (0: never)
  bool entryAngleShared = false;  // turned entries share one stroke angle: the turn is found once per pixel
  bool patternPerVertex = false;  // an anchored or scaled pattern's coordinate interpolated from the vertices
  bool patternRest = false;       // the object pattern read on a deforming mesh's rest pose (attributes 8-9)
  int rows = 1;                   // a two-dimensional palette: rows of `columns` entries, the row picked by `axis`
  int columns = 0;
  PaletteAxisKind axis = PaletteAxisKind::None;
  bool toneThreshold = false;     // the smooth path picks one of two levels per texel by its threshold (palette.glsl;
                                  // precomposited layers, intensity matching: FrameContext::paletteVariant)
};

// mesh.vert + mesh.frag. One shading per pass (the PATH_* blocks of mesh.frag).
enum class MeshShading : std::uint8_t {
  Mask,         // depth and stencil (the stencil path's mask); with a stroke source from the
                // field or the light, or a palette in object space, also the surface buffers
  Triangle,     // the CPU's per-triangle entry, a uniform per bucket
  Vertex,       // lit per vertex, matched per pixel
  Pixel,        // lit and matched per pixel
  Smooth,       // two bracketing entries blended
  Phong,        // reference, per pixel
  Gouraud,      // reference, per vertex
  LitTextured,  // benchmark floor: lighting times one fetch
  EyePosition,  // interpolated eye-space position (alpha -1 on back faces)
  EyeNormal,    // interpolated eye-space normal
  StrokeAngle,  // the hatching angle on screen and whether there is one (the stencil path's buffer)
  PatternCoordinate,  // the object-space pattern's coordinate and octave per pixel (the stencil path's buffer)
};
// Where a mesh pass takes each pixel's hatching angle from (orientation.glsl).
enum class StrokeSource : std::uint8_t { None, Field, Light, Fixed };
// What a palette pass writes: its texels, or (tests, the benchmark) the selection behind them.
enum class MeshOutput : std::uint8_t { Colour, Entry, Blend };
// A control-image palette pass (passes/control_palette_pass.h): the palette's texels with the
// parameter that blends them in as alpha (the share of diffuse light shadows block, or
// 1 - the occlusion factor).
enum class MeshControl : std::uint8_t { None, Shadow, Occlusion };

struct MeshProgram {
  MeshShading shading = MeshShading::Pixel;
  MeshOutput output = MeshOutput::Colour;
  std::optional<LightingFeatures> lighting;  // for the shadings that light on the GPU
  std::optional<PaletteVariant> palette;     // for the shadings that sample the palette
  bool materials = false;     // the mesh's own materials, colours and maps (GPU-lit shadings)
  bool materialMaps = false;  // ... some of which have a diffuse map
  bool vertexColours = false; // ... and the mesh has vertex colours
  bool materialUniform = false;  // ... one material per draw, from uniforms (else the table)
  // A see-through mesh in any shading: fragments its materials' alpha leaves out are discarded
  // (coverage.glsl; FrameContext::program sets it); reads the maps where materialMaps.
  bool alphaCoverage = false;
  StrokeSource stroke = StrokeSource::None;
  int shadowLayers = 0;       // lit through shadow maps with this many layers (shadows.glsl); 0: none
  bool occlusion = false;     // ambient and diffuse scaled by the baked ambient occlusion (attribute 7)
  bool screenOcclusion = false;  // ... or by this frame's screen-space occlusion (per-pixel shadings)
  MeshControl control = MeshControl::None;
  bool groundShadowMap = false;  // the ground's shadows read from its texture (shadows/ground_shadow_pass.h)
  // Palette shadings with a stroke source: write each pixel's stroke angle and entry at output 1
  // for one turned lookup per pixel afterwards (passes/turn_resolve_pass.h) instead of the texel.
  bool deferTurn = false;
  // The pixel and vertex shadings' colour: tone edges anti-aliased by matching at four points
  // of each pixel (mesh.frag's TONE_EDGES; RenderSettings::aa).
  bool toneEdges = false;
  // Mask shading: fragments at or in front of the layer before are discarded (depth peeling for
  // the hidden lines' occlusion levels, lines/occlusion_layers.h).
  bool peel = false;
};

// fullscreen.vert + quad.frag: the stencil path's quads and every path's background.
struct QuadProgram {
  enum class Kind : std::uint8_t { Background, Layer } kind = Kind::Background;
  bool backgroundImage = false;
  PatternMapping pattern = PatternMapping::Screen;  // layer quads: how pixels reach the layer
  bool layerSizesDiffer = false;  // layer quads: the palette's layers tile at different sizes
  bool filtered = false;          // layer quads: mapped and filtered (pattern.glsl)
  int orientBins = 0;     // layer quads: turned along the stroke angle (orientation.glsl)
  bool orientBuffer = false;  // ... read per pixel from the stroke-angle buffer (else fixed)
  bool opaque = false;        // layer quads: layers stored composited over the background, drawn
                              // opaque (their alpha may hold the tone thresholds, not coverage)
};

// fullscreen.vert + turn_resolve.frag: the turned lookups a DEFER_TURN mesh pass left, per pixel.
struct TurnResolveProgram {
  PaletteVariant palette;
  bool blend = false;  // two entries blended (the smooth path's)
};
// lines.vert + lines.frag: feature lines as screen-space quads.
struct LineProgram {
  bool sketchy = false;
  bool depthFalloff = false;
  bool dashed = false;  // dashes along the line (hidden lines by default, line sets' dash=ON,OFF)
  bool tapered = false; // strokes narrowed to points at their chains' ends (line sets' taper=PIXELS)
  bool byMaterial = false;  // only lines on faces of the materials a set takes (materials=NAME,...)
  bool textured = false;    // a coverage texture stretched along each stroke (texture=brush|FILE)
  bool byCurvature = false; // wider where the surface curves more (curvature=GAIN)
  bool occlusionLimit = false;  // hidden parts drawn only up to an occlusion level (occlusion=LEVEL)
  // colour=tone: lit with these lighting features, matched with this palette.
  std::optional<LightingFeatures> lighting = std::nullopt;
  std::optional<PaletteVariant> palette = std::nullopt;
};

// outline.vert + outline.geom + outline.frag: hardware outlines from back faces, or the
// charcoal rim (which reads the palette).
struct OutlineProgram {
  OutlineMethod method = OutlineMethod::Fatten;  // the user's choice (--outline)
  std::optional<PaletteVariant> palette;         // set: the charcoal rim instead, which reads the palette
  bool rim() const { return palette.has_value(); }
};

// strokes.vert + strokes.frag: painterly brush strokes, lit with the scene's lighting and
// coloured through the palette's matcher.
struct StrokeProgram {
  LightingFeatures lighting;
  PaletteVariant palette;
};

// fullscreen.vert + edges.frag: Sobel on the frame's depth and normals.
struct EdgeProgram {};


// marker.vert + marker.frag: the light marker.
struct MarkerProgram {};

// fullscreen.vert + supersample_resolve.frag: a supersampled frame box-filtered down.
struct SupersampleProgram {};
// fullscreen.vert + edge_filter.frag: the frame's post-process anti-aliasing filter (aa fxaa).
struct EdgeFilterProgram {};

// shadow_depth.vert + shadow_depth.frag: casters' depth for the shadow maps.
struct ShadowDepthProgram {
  bool alphaCoverage = false;  // a see-through caster (mesh.frag's ALPHA_COVERAGE)
  bool materialMaps = false;   // ... whose materials have maps
};

// fullscreen.vert + ground_shadow.frag: the ground's visibility per light from the shadow maps.
struct GroundShadowProgram {
  int lights = 1;  // 1..4
  int shadowLayers = 1;
};

// occlusion_bake.vert + occlusion_bake.frag: one direction of the ambient occlusion bake.
struct OcclusionBakeProgram {};

// triangle_light.vert + triangle_light.frag: per-triangle lighting and matching on the GPU.
struct TriangleLightProgram {
  LightingFeatures lighting;
  PaletteVariant palette;
  int shadowLayers = 0;
  bool occlusion = false;
};

// deform.comp: a deforming mesh's pose written into its vertex buffers
// (animation/gpu_deformation.h). `vectors`: direction vectors carried by the skin alone.
struct DeformProgram {
  bool skin = false;
  bool morph = false;
  bool vectors = false;
  static constexpr int kMaxActiveTargets = 32;  // morph targets with a weight, per pose
};

// A feature's own program (renderer/features/): its files and defines as it names them. A
// feature brings its shaders without a variant struct of its own; the cache keys it by them.
struct FeatureProgram {
  const char* vertexFile;
  const char* fragmentFile;
  std::vector<std::string> defines;
};

using ProgramVariant = std::variant<FeatureProgram, MeshProgram, QuadProgram, LineProgram, OutlineProgram, StrokeProgram, EdgeProgram, MarkerProgram, ShadowDepthProgram, OcclusionBakeProgram,
                                    TriangleLightProgram, GroundShadowProgram, TurnResolveProgram, DeformProgram, SupersampleProgram,
                                    EdgeFilterProgram>;

ProgramSource programSource(const ProgramVariant& variant);

}  // namespace npr::gl
