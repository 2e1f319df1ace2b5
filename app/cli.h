// The command line (CLI11). Bad arguments give a one-line message and exit status 2.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "app/camera_animation.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/palette_maker.h"
#include "renderer/paths/path_table.h"
#include "renderer/render_settings.h"

namespace npr {

struct Options {
  std::vector<std::string> models;  // the first is shown; --benchmark uses all
  std::vector<std::string> palettes;
  std::optional<RenderPath> path;
  bool listPaths = false;
  std::optional<MatchMode> match;
  std::optional<float> rangeScale;
  glm::ivec2 size{1280, 720};
  std::optional<glm::vec3> light;
  std::optional<glm::vec3> camera;  // yaw, pitch (degrees), distance (model radii)
  bool headless = false;
  int frames = 0;  // 0: run until closed (window) or 1 (headless)
  std::string screenshot;
  bool info = false;
  std::string paletteInfo;
  // --make-palette IMAGE (--ladder STEP | --tam) --levels N --out DIR
  std::string makePalette;
  std::optional<Ladder> ladder;
  bool tam = false;
  int levels = 10;
  std::string paletteSheet;  // --palette-sheet DIR
  std::string style;         // --style NAME|FILE (palettes/styles/NAME.style)
  bool benchmark = false;
  bool allMatchModes = false;  // --benchmark --match all
  std::string outDir = "benchmark-results";
  bool gouraud = false;
  bool materials = true;
  std::vector<std::pair<std::string, std::string>> materialPalettes;  // --palette-for MATERIAL=FILE
  CameraAnimation animation;  // --animate
  std::optional<PatternSpace> pattern;  // --pattern
  bool patternNoRotation = false;       // --pattern-no-rotation
  std::optional<float> patternScale;    // --pattern-scale (default: the window's content scale)
  bool patternLinear = false;           // --pattern-filter linear
  std::optional<OrientSettings> orient; // --orient
  std::optional<int> orientBins;        // --orient-bins
  bool ground = false;                  // --ground
  bool shadows = false;                 // --shadows
  bool occlusion = false;               // --occlusion
  std::optional<float> occlusionStrength;  // --occlusion-strength
  std::optional<OcclusionMethod> occlusionMethod;  // --occlusion-method
  std::string shadowPalette, occlusionPalette;  // --shadow-palette, --occlusion-palette (control images)
  TriangleLighting triangleLighting = TriangleLighting::Auto;  // --triangle-lighting
  std::string saveFrames;     // --save-frames DIR
  std::string svg;            // --svg FILE: the last frame's feature lines as SVG
  bool svgRaster = false;     // --svg-raster: with the frame embedded underneath
  int turntable = 0;
  int tile = 0;               // --tile N: render the still in N x N tiles (a poster); automatic beyond the GL limit          // --turntable N: N frames of one full orbit, headless, frames and a GIF
  bool naiveStencil = false;
  // Lines and tone (overlay toggles too)
  bool strokes = false;                   // --strokes
  std::optional<float> strokeDensity;     // --stroke-density
  std::optional<int> strokeBudget;        // --stroke-budget
  std::optional<glm::vec2> strokeSize;    // --stroke-size LxW
  std::optional<LineSettings> lineKinds;  // --lines: which kinds (the rest of it is defaults)
  std::optional<OutlineMethod> outlineMethod;  // --outline
  std::optional<float> outlineOffset;          // --outline-offset
  std::optional<float> creaseAngle, lineWidth;
  bool sketchy = false, lineFalloff = false;
  std::optional<ToneModel> tone;
  std::vector<float> bands;
};

// Returns the options, or an exit status (0 after --help, 2 for bad arguments) with the
// message already printed.
struct ParseOutcome {
  std::optional<Options> options;
  int exitCode = 0;
};
ParseOutcome parseCommandLine(int argc, char** argv);

// The app's one way of ending on a runtime failure (a file that fails to load, a render that
// fails, no display): prints "npr-viewer: MESSAGE" on stderr and returns exit status 1.
int reportFailure(const std::string& message);

}  // namespace npr
