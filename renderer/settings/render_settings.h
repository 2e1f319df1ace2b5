// What the user chooses: the render path, matching, stencil refinements, lines and the
// features' settings (each a row of the app's settings table), and apart from them the
// renderer's own tuning, which only tests and benchmarks turn (RenderTuning).
#pragma once

#include <cstdint>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/settings/choices.h"

namespace npr {

// How hardware outlines are made from the back faces (lines/hardware_outline_pass.h): their
// edges as wide quads, the faces pulled towards the eye in proportion to depth, or the faces
// fattened on screen (Raskar and Cohen; even widths, the default).
enum class OutlineMethod { Edges, Offset, Fatten };

// Float text that parses back to the same float, as short as it can be (style files, the
// settings reference, line sets).
std::string formatFloat(float v);

// A line set (`line-set` in style files, --line-set): some object-space kinds drawn in a style
// of their own, as Freestyle's and Pencil+'s line sets are. Sets draw in the order given, over
// the kinds `lines` names that no set takes (which keep the line settings' own style).
struct LineSet {
  std::uint8_t kinds = 0;  // bit EdgeKind: silhouette 1, crease 2, boundary 4, material 8, intersection 16, suggestive 32
  enum class Visibility : std::uint8_t { Visible, Hidden, Both } visibility = Visibility::Visible;
  float width = 2.0f;                 // pixels
  std::optional<glm::vec3> colour;    // none: each kind's colour (silhouette-colour, ...)
  // colour=tone: each line in the average colour of the palette entry its lit tone matches (lit
  // at the line with the surface's normal, as the painterly strokes are), over `colour`.
  bool toneColour = false;
  glm::vec2 dash{0.0f};               // pixels on, off; on 0: solid
  bool falloff = false;               // thinner with distance
  bool sketchy = false;
  // Each stroke (a chain of edges, lines/line_chains.h) narrows to a point over this many
  // pixels at both ends (0: blunt).
  float taper = 0.0f;
  // The objects it draws on, by name, '*' and '?' as wildcards (empty: every object and the
  // scene's intersections; a set naming objects leaves intersections to the others).
  std::vector<std::string> objects;
  // The materials it draws on, by name, wildcards as for objects (empty: every one): a line
  // is taken when a face on either side has one. Such a set draws over the base style (it takes
  // no kind from it) and leaves the scene's intersections to the others.
  std::vector<std::string> materials;
  // Coverage stretched along each stroke (lines/stroke_textures.h): `brush` (the painterly
  // strokes' first brush) or an image file; empty: none.
  std::string texture;
  // Width x (the surface's curvature / the mesh's median)^curvature, within 1/4..4: positive
  // draws tight bends and thin parts heavier, negative lighter; 0: off.
  float curvature = 0.0f;
  // Hidden parts drawn only where at most this many surfaces lie in front of them (Blender Line
  // Art's occlusion level; every surface counts, so a closed part's far side is at level 1 and
  // whatever it encloses at 2 or more); 0: every hidden part. Each level costs one depth-only
  // pass of the scene in frames that draw the set (lines/occlusion_layers.h).
  int occlusion = 0;
  bool takesMaterial(const std::string& name) const;
  static constexpr float kMinWidth = 0.1f, kMaxWidth = 64.0f, kMaxDash = 1000.0f, kMaxTaper = 1000.0f, kMaxCurvatureGain = 4.0f;
  static constexpr int kMaxOcclusion = 3;
  bool has(int kind) const { return (kinds >> kind) & 1u; }
  // Whether it draws on the object named `object` (null: the scene's intersection lines).
  bool appliesTo(const std::string* object) const;
};
// Sets, one per line (or separated by ';'): `KINDS [visibility=visible|hidden|both] [width=W]
// [colour=R,G,B|tone] [dash=ON,OFF] [taper=PIXELS] [texture=brush|FILE] [curvature=GAIN] [occlusion=LEVEL] [falloff=on|off] [sketchy=on|off]
// [objects=NAME,...] [materials=NAME,...]`, or `none`. On failure `why`
// says which set and what is wrong, and `sets` is unchanged.
bool parseLineSets(const std::string& text, std::vector<LineSet>& sets, std::string* why);
std::string formatLineSets(const std::vector<LineSet>& sets);  // one set per line; "none" when empty

// Lines drawn over any path (object-space feature edges, lines/feature_edges.h; image-space
// edges, lines/image_edges_pass.h; hardware outlines and the charcoal rim,
// lines/hardware_outline_pass.h).
struct LineSettings {
  bool silhouettes = false, creases = false, boundaries = false;
  bool materials = false;  // material boundaries: edges between faces of different materials
  bool intersections = false;  // where surfaces cross, in one object or between two (lines/intersection_lines.h)
  // Suggestive contours (lines/suggestive_contours.h): where a contour would appear under a
  // small change of view; `suggestiveThreshold` is DeCarlo et al.'s t_d (times the mesh's radius
  // squared): higher keeps only the strongest.
  bool suggestive = false;
  float suggestiveThreshold = 1.0f;
  static constexpr float kMinSuggestiveThreshold = 0.0f, kMaxSuggestiveThreshold = 1000.0f;
  // The chosen object-space kinds' hidden parts too, dashed (`--hidden-lines`).
  bool hidden = false;
  float creaseAngle = 60.0f;  // degrees
  float width = 2.0f;         // pixels
  glm::vec3 silhouetteColour{0.0f}, creaseColour{1.0f}, boundaryColour{0.15f, 0.1f, 0.05f}, materialColour{0.25f, 0.2f, 0.15f};
  glm::vec3 intersectionColour{0.0f};
  glm::vec3 suggestiveColour{0.12f, 0.1f, 0.1f};
  bool depthFalloff = false;
  bool sketchy = false;
  // Image space: Sobel on the depth and normal buffers, thresholded, drawn as a post-process.
  bool imageSpace = false;
  float imageThreshold = 0.4f;
  // Hardware outlines: the silhouette drawn from back faces in the silhouette colour, no
  // adjacency needed (`--lines hardware`).
  bool hardware = false;
  OutlineMethod outline = OutlineMethod::Fatten;
  float outlineOffset = 0.005f;  // Offset: back faces pulled this fraction of their depth towards the eye
  // Charcoal rim (`--lines rim`): front faces with 0 < N.V < rimLimit fattened outward by the
  // line width and drawn with the palette entry of their tone (1 + N.V) / 3.
  bool rim = false;
  float rimLimit = 0.1f;
  static constexpr float kMinOutlineOffset = 0.0f, kMaxOutlineOffset = 0.2f;
  std::vector<LineSet> sets;
  // The object-space kinds `lines` names (bit EdgeKind).
  std::uint8_t namedKinds() const;
  // The object-space kinds drawn (bit EdgeKind): those `lines` names and those the sets take.
  std::uint8_t drawnKinds() const {
    std::uint8_t k = namedKinds();
    for (const LineSet& s : sets) k |= s.kinds;
    return k;
  }
  // Those drawn in the line settings' own style on the object named `object` (null: the
  // scene's intersections, which only sets naming no object take): named by `lines` and taken
  // there by no set.
  std::uint8_t baseKinds(const std::string* object = nullptr) const {
    std::uint8_t k = namedKinds();
    for (const LineSet& s : sets)
      if (s.appliesTo(object) && s.materials.empty()) k &= std::uint8_t(~s.kinds);
    return k;
  }
  // The kinds found on each mesh (all but the scene's intersections).
  bool edgeKinds() const { return (drawnKinds() & ~16u) != 0; }
  bool objectSpace() const { return drawnKinds() != 0; }
};

// The object-space line kinds, one row each, in EdgeKind order (lines/feature_edges.h; bit k of
// a kinds mask is row k): what --lines, line sets, the style file, the overlay, the colour
// settings, the line shader's colours and the SVG groups read. A new kind is a row here and the
// code that finds its lines.
struct LineKindRow {
  const char* name;         // "silhouette": in --lines and line sets (the plural is accepted too)
  const char* plural;       // "silhouettes": also the SVG group's id
  const char* colourKey;    // its colour setting
  const char* colourLabel;  // the overlay's
  const char* colourHelp;
  bool LineSettings::*on;
  glm::vec3 LineSettings::*colour;
};
inline constexpr LineKindRow kLineKinds[] = {
    {"silhouette", "silhouettes", "silhouette-colour", "silhouette colour", "Silhouettes' colour R,G,B", &LineSettings::silhouettes,
     &LineSettings::silhouetteColour},
    {"crease", "creases", "crease-colour", "crease colour", "Creases' colour R,G,B", &LineSettings::creases, &LineSettings::creaseColour},
    {"boundary", "boundaries", "boundary-colour", "boundary colour", "Boundaries' colour R,G,B", &LineSettings::boundaries,
     &LineSettings::boundaryColour},
    {"material", "materials", "material-colour", "material line colour", "Material boundaries' colour R,G,B", &LineSettings::materials,
     &LineSettings::materialColour},
    {"intersection", "intersections", "intersection-colour", "intersection colour", "Intersection lines' colour R,G,B",
     &LineSettings::intersections, &LineSettings::intersectionColour},
    {"suggestive", "suggestive-contours", "suggestive-colour", "suggestive colour", "Suggestive contours' colour R,G,B",
     &LineSettings::suggestive, &LineSettings::suggestiveColour},
};
inline constexpr int kLineKindCount = int(std::size(kLineKinds));
// The row named `name` (singular or plural), or -1.
int lineKindIndex(const std::string& name);

inline std::uint8_t LineSettings::namedKinds() const {
  std::uint8_t k = 0;
  for (int i = 0; i < kLineKindCount; ++i)
    if (this->*kLineKinds[i].on) k |= std::uint8_t(1u << i);
  return k;
}

// Where the palette's pattern lives: fixed to the screen (the original), anchored to the
// object's motion while staying flat (patterns/pattern_tracker.h), or glued to the surface in
// object space (triplanar, octaves by screen scale: shaders/pattern.glsl).
enum class PatternSpace { Screen, Anchored, Object };

// Where hatching strokes point (`--orient`): the texture's own angle (the original), along the
// surface's curvature (orientation/direction_field.h), across the light's gradient on the
// surface, or a fixed screen angle. Each palette entry with a dominant direction
// (palette/palette_orientation.h) is turned per pixel so that direction runs along this one;
// the turn is quantised to `bins` steps over 180 degrees and the two nearest are blended, so
// strokes stay straight within a step.
enum class OrientSource { None, Curvature, Light, Fixed };
// Where the triangle, vertex, pixel and smooth paths turn their lookups: in the mesh pass, or once per
// pixel after it (passes/turn_resolve_pass.h); Auto: after it where the model's triangles
// span under Renderer's threshold of pixels each (dense meshes), in the mesh pass elsewhere.
enum class TurnPlacement { Auto, InMeshPass, Resolved };
struct OrientSettings {
  OrientSource source = OrientSource::None;
  float degrees = 0.0f;  // Fixed: counter-clockwise from the screen's x axis
  int bins = 8;          // 2..64
  static constexpr int kMinBins = 2, kMaxBins = 64;
  bool operator==(const OrientSettings& o) const { return source == o.source && degrees == o.degrees && bins == o.bins; }
};
// "none", "curvature", "light" or "fixed:DEGREES"/"DEGREES"; the parse accepts what the name
// gives back, and a number alone is a fixed angle.
std::string orientName(const OrientSettings& o);
std::optional<OrientSettings> parseOrient(const std::string& s);
// "none" or kinds separated by commas (silhouette, crease, boundary, image, hardware, rim;
// plurals too): sets
// exactly those kinds on in `lines`. False, `lines` untouched and the kind in `unknown`, on a
// kind it does not know.
bool parseLineKinds(const std::string& list, LineSettings& lines, std::string* unknown = nullptr);

// Painterly brush strokes drawn over the path (strokes/brush_stroke_pass.h): particles seeded
// once on the surface at `density` per unit area (the model fitted to the unit sphere), at
// most `budget`, each a brush-textured quad of `length` x `width` pixels. Beyond the framing
// distance fewer are drawn, faded in and out over a band of ranks (`fade` off: cut, which pops).
struct StrokeSettings {
  bool on = false;
  float density = 3000.0f;
  int budget = 200000;
  float length = 16.0f, width = 6.0f;
  static constexpr float kMinDensity = 1.0f, kMaxDensity = 1e6f, kMaxSize = 256.0f;
  static constexpr int kMaxBudget = 4000000;
};
// "LxW" in pixels, each in 1..kMaxSize (the command line and style files share it).
std::optional<glm::vec2> parseStrokeSize(const std::string& s);

// Where the per-triangle paths (stencil, triangle) light their triangles: on the CPU (the
// original), on the GPU with the entries read back (shading/gpu_triangle_lighting.h), or
// `auto`: the GPU when shadows are on (the CPU lighting has no shadow maps), else the CPU.
enum class TriangleLighting { Auto, Cpu, Gpu };

// Where a deforming mesh (skins, morph targets) is posed (animation/gpu_deformation.h): `gpu`
// on the GPU, into the buffers every pass draws from, and on the CPU too when the frame reads
// the mesh there (per-triangle paths, object-space lines, painterly strokes, the anchored
// pattern), without uploading it; `cpu` on the CPU and uploaded, as before; `auto` as `gpu`,
// except on a software rasterizer when the frame reads the mesh on the CPU: there as `cpu`
// (poseTargets in renderer.h has the figures). Without compute shaders (OpenGL 4.3) on the CPU.
enum class PosePlacement { Auto, Cpu, Gpu };

// Where ambient occlusion comes from: baked per vertex once per mesh (shadows/occlusion_bake.h)
// or estimated per pixel every frame from what the frame shows (features/occlusion/screen_occlusion_pass.h;
// the per-pixel shadings only: pixel, smooth, reference's Phong, and the control palettes).
enum class OcclusionMethod { Baked, Screen };

// The smooth path between two levels (RenderSettings::toneBlend).
enum class ToneBlend { Mix, Threshold };

// The depth cue (features/depth_cue/): the paper blended over tone and lines by distance
// through the scene, from `start` to `end` (fractions of the scene's depth: 0 its front, 1
// its back), at most `strength`.
struct DepthCueSettings {
  bool on = false;
  float start = 0.2f, end = 1.0f;
  float strength = 0.8f;
};

// The vignette (features/vignette): the picture fades into the paper toward the frame's edges.
// Radius and softness in units of the half-diagonal (0 the centre, 1 the corners).
struct VignetteSettings {
  bool on = false;
  float radius = 0.6f, softness = 0.4f;
  float strength = 1.0f;
};

// Not user settings: the renderer's own choices, which tests and benchmarks turn to compare
// (the same picture by another way, or the cost a choice saves). No option, style key or
// panel widget sets them.
struct RenderTuning {
  // The ground's shadows read from a texture drawn whenever the maps are (shadows/
  // ground_shadow_pass.h) rather than filtered per pixel; off: per pixel, to compare.
  bool groundShadowTexture = true;
  // Drop back faces where none can show: a closed mesh (Mesh::closed) wholly beyond the near
  // plane. Off: every face is rasterized, as the original did (the same picture, slower).
  bool cullHiddenBackFaces = true;
  // Where turned lookups happen (TurnPlacement): by density, or forced either way.
  TurnPlacement turnPlacement = TurnPlacement::Auto;
  // Painterly strokes beyond the framing distance fade in and out over a band of ranks (off:
  // cut, which pops).
  bool strokeFade = true;
  // Small static objects merged into batches for the surface passes where the frame allows
  // (scene/scene_batches.h); off: every object drawn alone, to compare.
  bool batchObjects = true;
};

// Whether and how the palette is fitted onto the tones on screen (RenderSettings::toneRange).
enum class ToneRange : std::uint8_t { Fixed, Auto, PerObject };

// Anti-aliasing, cheapest first. Edges: the pixel and vertex paths' tone edges smoothed in the
// shader (mesh.frag's TONE_EDGES: the match taken at four points of each pixel, each point's
// entry shown at the pixel's own texel, so the pattern is untouched); lines always keep their
// own one-pixel soft rim. SsaaK (K = 2..4) adds supersampling (frame/supersample.h): the frame
// drawn at K times the viewport's width and height, every size in pixels (lines, dashes,
// strokes, the pattern's texel) times as much, then box-filtered down: silhouettes and the
// per-triangle paths' edges are smoothed too, at about K^2 the fill. Fxaa adds a post-process
// filter over the frame drawn at its own size (shaders/edge_filter.frag): one more full-screen
// pass, but the palette's pattern is softened with the edges.
enum class AntiAliasing : std::uint8_t { Off = 0, Edges = 1, Ssaa2 = 2, Ssaa3 = 3, Ssaa4 = 4, Fxaa = 5 };
// The supersampling factor: 1 but for SsaaK.
inline int supersampleFactor(AntiAliasing a) { return a >= AntiAliasing::Ssaa2 && a <= AntiAliasing::Ssaa4 ? int(a) : 1; }
inline bool postFiltered(AntiAliasing a) { return a == AntiAliasing::Fxaa; }
inline bool toneEdgesSmoothed(AntiAliasing a) { return a != AntiAliasing::Off; }

struct RenderSettings;
// `s` with every size given in pixels (line widths, dashes and tapers, stroke sizes, the
// pattern's texel) times `k`: the same picture drawn at k times the resolution.
RenderSettings pixelSizesScaled(const RenderSettings& s, float k);

struct RenderSettings {
  RenderPath path = RenderPath::Pixel;
  MatchMode match = MatchMode::Intensity;
  float rangeScale = 1.0f;
  // Fit the palette's levels onto the tones the visible surfaces show (palette/tone_range.h;
  // the range scale then spreads about them): the whole scene's (Auto), or each object's own
  // (PerObject). Fixed: the palette's own range, as the original.
  ToneRange toneRange = ToneRange::Fixed;
  // Between the two levels the smooth path brackets a tone with: blended, or whole texels of one
  // or the other by each texel's threshold (palette/tone_thresholds.h), where the palette has them.
  ToneBlend toneBlend = ToneBlend::Mix;
  // A palette with rows (palette.h): the row follows the surface (its distance or facing); off,
  // the first row only.
  bool paletteAxis = true;
  std::vector<float> bands;  // cel band thresholds (see PaletteMatcher::create); empty: nearest level
  // Light each face with the model's own materials, vertex colours and texture maps (when it
  // has any); off: the lighting state's one material, as the original.
  bool materials = true;
  bool referenceGouraud = false;  // `reference` path: per-vertex instead of per-pixel lighting
  PatternSpace pattern = PatternSpace::Screen;
  bool patternFollowsRotation = true;  // anchored: turn the pattern with the object (else only move and scale)
  // The size of a palette texel in screen pixels (--pattern-scale): 1 draws palettes texel for
  // pixel (the original); a high-DPI window defaults to its content scale so hatching keeps its
  // physical size. Below 1 the palette's mip levels keep its tone (palette_mipmaps.h).
  float patternScale = 1.0f;
  // Where the pattern is mapped (scaled or anchored): the nearest texel of the mip level (one
  // fetch, the default) or bilinear in linear light (no stair-steps on turned or non-integer
  // scaled patterns; about 15% of a bunny frame on llvmpipe).
  bool patternLinearFilter = false;
  static constexpr float kMinPatternScale = 0.125f, kMaxPatternScale = 16.0f;
  // Anti-aliasing (AntiAliasing): off in the renderer (its path tests compare against the
  // original); the viewer starts at Edges (app/viewer_defaults.h).
  AntiAliasing aa = AntiAliasing::Off;
  static constexpr int kMaxSupersample = 4;
  OrientSettings orient;
  // A ground plane under the model, drawn with the same palette and path (mesh/ground_plane.h).
  bool ground = false;
  // Cast shadows from every enabled light in the GPU-lit paths (shadows/shadow_maps.h).
  bool shadows = false;
  // Ambient occlusion baked per vertex (shadows/occlusion_bake.h) scales ambient and diffuse in
  // the GPU-lit paths: by mix(1, occlusion, strength).
  bool occlusion = false;
  float occlusionStrength = 1.0f;
  OcclusionMethod occlusionMethod = OcclusionMethod::Baked;
  // Screen-space occlusion's reach, in model radii (the hemisphere's radius around each pixel).
  float screenOcclusionRadius = 0.3f;
  // Draw the control-image palettes the renderer holds (off: the main palette alone, to
  // compare; passes/control_palette_pass.h).
  bool controlPalettes = true;
  TriangleLighting triangleLighting = TriangleLighting::Auto;
  PosePlacement deform = PosePlacement::Auto;
  // Stencil path refinements over the original (off = the naive full-screen version):
  bool stencilScissor = true;     // bound each bucket's quads to its triangles' screen rectangle
  bool stencilSkipEmpty = true;   // draw nothing for buckets with no triangle
  // Mark every bucket's pixels (the stencil holding the bucket's number) before any quad is
  // drawn: each pixel then gets the quads of the bucket it shows only, and the masks can write
  // the surface buffers as they mark. Off: the original's mask, quad, quad per bucket.
  bool stencilMasksFirst = true;
  LineSettings lines;
  StrokeSettings strokes;
  DepthCueSettings depthCue;
  VignetteSettings vignette;
  RenderTuning tuning;
};

}  // namespace npr
