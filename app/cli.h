// The command line (CLI11). Bad arguments give a one-line message and exit status 2.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "app/camera_animation.h"
#include "app/headless/frame_sequence.h"
#include "app/scene_layout.h"
#include "app/settings/look.h"
#include "app/video/video_encoder.h"
#include "renderer/gl/gpu_choice.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/palette_maker.h"
#include "renderer/paths/path_table.h"
#include "renderer/settings/render_settings.h"

namespace npr {

// What the command line asks for: the settings it names (rows of the settings table, applied
// over the style and the palette's defaults) and the actions it takes.
struct Options {
  std::vector<std::string> models;  // shown together as one scene; --benchmark measures each
  Layout layout = Layout::File;     // --layout: how several files are placed
  int cameraFromFile = -1;
  bool fileLights = true;
  bool splitObjects = false;        // --split-objects: OBJ groups as objects           // --no-file-lights: the viewer's light even where the file has lights          // --camera-from-file N: the scene's camera N (1-based; -1 none)
  std::vector<std::pair<std::string, std::string>> objectPalettes;  // --object-palette OBJECT=FILE
  std::vector<std::pair<std::string, float>> objectDetails;         // --object-detail OBJECT=VALUE
  std::vector<std::pair<std::string, float>> materialDetails;       // --material-detail MATERIAL=VALUE
  std::string playAnimation;  // --animation NAME|NUMBER|all|none (empty: all)
  double time = 0.0;          // --time SECONDS: the scene's clock at the first frame
  bool play = true;           // the window's clock runs from the start (--paused: not); headless sequences always run it
  double fps = 30.0;          // --fps: scene frames per second of headless sequences and their GIF
  std::vector<std::string> palettes;
  std::vector<SettingValue> settings;  // in the table's order
  bool listPaths = false;
  glm::ivec2 size{1280, 720};
  std::optional<glm::vec3> camera;  // yaw, pitch (degrees), distance (model radii)
  bool headless = false;
  bool noPanel = false;  // --no-panel: the window opens with its panel hidden (F1 shows it)
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
  std::string styleSheet;    // --style-sheet FILE
  std::string style;         // --style NAME|FILE (palettes/styles/NAME.style)
  std::string saveStyle;     // --save-style FILE: the look as a style file, after start-up
  bool settingsReference = false;  // --settings-reference: the settings table as Markdown
  GpuRequest gpu;                  // --gpu INDEX|NAME|auto|surfaceless (or NPR_GPU): the headless device
  bool glInfo = false;             // --gl-info: what the headless context runs on
  bool verbose = false;            // --verbose: every load warning, not the first three of each kind
  bool version = false;            // --version
  bool benchmark = false;
  bool allMatchModes = false;  // --benchmark --match all
  std::string outDir = "benchmark-results";
  std::vector<std::pair<std::string, std::string>> materialPalettes;  // --palette-for MATERIAL=FILE
  CameraAnimation animation;  // --animate
  std::string saveFrames;     // --save-frames DIR
  std::string svg;            // --svg FILE: the last frame's feature lines as SVG
  bool svgRaster = false;     // --svg-raster: with the frame embedded underneath
  bool svgFill = false;       // --svg-fill: the shaded picture as regions filled with the palette's textures
  int turntable = 0;          // --turntable N: N frames of one full orbit, headless, frames and a GIF
  std::string video;          // --video FILE: the sequence as .mp4 (H.264), .webm (VP9) or .gif
  int videoQuality = VideoSpec::kDefaultQuality;  // --video-quality: CRF, 0 (lossless) to 51
  std::optional<FrameRange> frameRange;  // --frame-range FIRST-LAST: only those frames of the sequence
  int tile = 0;               // --tile N: render the still in N x N tiles (a poster); automatic beyond the GL limit

  // The value the command line gives the setting `key`, or null.
  const SettingValue* setting(const std::string& key) const;
  // The settings over a default look (for runs with no viewer state: the benchmark).
  Look look() const;
};

// Returns the options, or an exit status (0 after --help, 2 for bad arguments) with the
// message already printed.
struct ParseOutcome {
  std::optional<Options> options;
  int exitCode = 0;
};
ParseOutcome parseCommandLine(int argc, char** argv);

// The app's one way of telling the user something on stderr: "npr-viewer: MESSAGE", with
// control characters and invalid UTF-8 from files and paths escaped (core/printable.h).
void tellUser(const std::string& message);

// The app's one way of ending on a runtime failure (a file that fails to load, a render that
// fails, no display): prints "npr-viewer: MESSAGE" on stderr and returns exit status 1.
int reportFailure(const std::string& message);

}  // namespace npr
