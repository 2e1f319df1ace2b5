// Command-line parsing and validation (see cli.h). The settings' options come from the
// settings table (app/settings/); what is written here are the actions.
#include "app/cli.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>

#include "app/data_directory.h"
#include "app/settings/style_file.h"
#include "app/man_page.h"
#include "renderer/core/printable.h"

namespace npr {
namespace {

// The group --help shows; the others show with --help-all.
constexpr const char* kCommonTasks = "Common tasks";

bool parseFloats(const std::string& s, int n, float* out) {
  std::stringstream ss(s);
  std::string part;
  int i = 0;
  while (std::getline(ss, part, ',')) {
    if (i >= n) return false;
    char* end = nullptr;
    out[i] = std::strtof(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(out[i])) return false;
    ++i;
  }
  return i == n;
}

int fail(const std::string& msg) {
  tellUser(msg + " (see --help)");
  return 2;
}

}  // namespace

const SettingValue* Options::setting(const std::string& key) const {
  for (const SettingValue& v : settings)
    if (v.row->key == key) return &v;
  return nullptr;
}

Look Options::look() const {
  Look l;
  for (const SettingValue& v : settings) (void)v.row->parse(v.value, l);
  return l;
}

ParseOutcome parseCommandLine(int argc, char** argv) {
  // --help shows the common tasks; --help-all, and the manual page, every group.
  bool everything = false;
  for (int i = 1; i < argc; ++i) everything = everything || std::strcmp(argv[i], "--help-all") == 0 || std::strcmp(argv[i], "--man-page") == 0;
  auto group = [everything](const char* name) { return everything || std::strcmp(name, kCommonTasks) == 0 ? std::string(name) : std::string(); };

  CLI::App app{"npr-viewer: palette-based non-photorealistic rendering of meshes.\n"
               "Lights each triangle or pixel with the OpenGL lighting model and shows the palette texture\n"
               "whose average colour or intensity matches best, in screen space."};
  app.name("npr-viewer");
  app.footer(everything ? "Every setting is also a style-file key (the README's settings reference).\n"
                        : "--help-all lists every option: scene, animation, output, palette tools, diagnostics, and the\n"
                          "settings (palette and tone, render path, pattern, light, shadows, occlusion, strokes, lines, ...),\n"
                          "each of which is also a style-file key.");
  app.set_help_flag("-h,--help", "Print the common options and exit")->group(kCommonTasks);
  bool helpAll = false;
  app.add_flag("--help-all", helpAll, "Print every option, in groups, and exit")->group(group(kCommonTasks));
  Options o;
  std::string size, camera;
  std::vector<std::string> paletteFor;
  std::string animate;
  std::string layout;
  std::vector<std::string> objectPalette, objectDetail, materialDetail;
  std::string gpu, ladder, frameRange;
  bool manPageWanted = false, naiveStencil = false;

  // What most runs need: open, style, palette, output.
  std::string g = group(kCommonTasks);
  app.add_option("model", o.models, "Mesh or scene files (OBJ, glTF/GLB, PLY, OFF, STL, OM), shown together; default models/bunny.obj")
      ->type_name("FILE")->group(g);
  app.add_option("--style", o.style,
                 "A look from a style file: NAME (palettes/styles/NAME.style: crosshatch, pencil, charcoal, painterly, technical, cel, stipple, woodcut, illustrated, screentone) "
                 "or FILE; options given beside it win")
      ->type_name("NAME|FILE")->group(g);
  app.add_option("--palette", o.palettes, "Palettes by shipped name, folder or .palette file (keys 1-9 cycle them); default crosshatch")
      ->type_name("NAME|FILE")->group(g);
  app.add_option("--size", size, "Frame size WxH: the headless frame's, or the window's (default 1280x720)")->type_name("WxH")->group(g);
  app.add_option("--camera", camera, "Camera YAW,PITCH,DISTANCE (degrees, degrees, model radii)")->type_name("YAW,PITCH,DIST")->group(g);
  app.add_flag("--headless", o.headless, "Render through EGL with no window")->group(g);
  app.add_option("--screenshot", o.screenshot, "Write the last frame to FILE (PNG, TGA, EXR, ...)")->type_name("FILE")->group(g);
  app.add_option("--turntable", o.turntable,
                 "Render N frames of one full orbit headless into --save-frames DIR (default turntable/), with DIR/turntable.gif")
      ->type_name("N")->group(g);
  app.add_option("--video", o.video,
                 "Write the sequence (--turntable, or --frames with --animate or an animated scene) to FILE: .mp4 (H.264), .webm (VP9) "
                 "or .gif, at --fps frames a second")
      ->type_name("FILE")->group(g);
  app.add_option("--save-style", o.saveStyle, "Write the look (style, palette and every setting given) to FILE as a style file")
      ->type_name("FILE")->group(g);
  app.add_option("--style-sheet", o.styleSheet,
                 "Write FILE (PNG): the model in every shipped style, one labelled cell each, to pick a style by looking "
                 "(--size is the whole sheet's; the other options apply to every cell)")
      ->type_name("FILE")->group(g);
  app.add_flag("--version", o.version, "Print the version and exit")->group(g);

  g = group("Scene and window");
  app.add_option("--layout", layout, "Several files: placed as their files place them (file, the default), or set apart in a row or a grid")
      ->type_name("file|row|grid")->group(g);
  app.add_option("--camera-from-file", o.cameraFromFile, "View through the scene file's camera N (1 is the first; --info lists them)")
      ->type_name("N")->group(g);
  app.add_flag("--split-objects", o.splitObjects, "OBJ files: each 'o' and 'g' group an object of its own (its own palette, visibility)")->group(g);
  app.add_flag_function("--no-file-lights", [&o](std::int64_t) { o.fileLights = false; },
               "Light with the viewer's light even where the scene file has lights (glTF KHR_lights_punctual; by default its own light it)")
      ->group(g);
  app.add_flag_function("--file-lights", [&o](std::int64_t) { o.fileLights = true; }, "")->group("");
  app.add_option("--object-palette", objectPalette,
                 "OBJECT=PALETTE: draw the object named OBJECT (or numbered, from 1, as --info lists them) with its own palette (repeatable)")
      ->type_name("OBJECT=PALETTE")->group(g);
  app.add_option("--object-detail", objectDetail,
                 "OBJECT=VALUE: the object's detail in [0, 1], which picks the row of a palette with 'axis detail' (repeatable; default 0)")
      ->type_name("OBJECT=VALUE")->group(g);
  app.add_option("--palette-for", paletteFor,
                 "MATERIAL=PALETTE: draw the model's material MATERIAL with its own palette (repeatable; needs --materials on)")
      ->type_name("MATERIAL=PALETTE")->group(g);
  app.add_option("--material-detail", materialDetail,
                 "MATERIAL=VALUE: the detail in [0, 1] of the faces of material MATERIAL, in place of their object's, for a palette with "
                 "'axis detail' (repeatable; needs --materials on)")
      ->type_name("MATERIAL=VALUE")->group(g);
  app.add_flag("--no-panel", o.noPanel, "The window opens with its settings panel hidden (F1 shows it)")->group(g);

  g = group("Animation");
  app.add_option("--animation", o.playAnimation,
                 "The scene's animation to play: its NAME, its NUMBER from 1 (--info lists them), all (the default) or none (the rest pose)")
      ->type_name("NAME|N|all|none")->group(g);
  app.add_option("--time", o.time, "Pose the scene at SECONDS of its animations' time (the first frame's, when it plays)")
      ->type_name("SECONDS")->group(g);
  app.add_flag_function("--paused", [&o](std::int64_t) { o.play = false; },
                        "The window opens with the scene's animations paused at their first frame (by default they play; space plays and pauses)")
      ->group(g);
  app.add_flag_function("--play", [&o](std::int64_t) { o.play = true; }, "")->group("");  // the default; kept for scripts
  app.add_option("--fps", o.fps, "Headless sequences (--frames, --turntable, --video): frames per second, the clock's step per frame (1..1000; default 30)")
      ->type_name("N")->group(g);
  app.add_option("--frames", o.frames, "Render N frames, then exit (benchmark: frames of scripted motion, default 120)")->type_name("N")->group(g);
  app.add_option("--animate", animate,
                 "Move the camera every frame: orbit:DEGREES, pan:DX,DY (pixels), zoom:FACTOR, comma-separated (e.g. orbit:1,zoom:1.01)")
      ->type_name("MOTION")->group(g);

  g = group("Output");
  app.add_option("--save-frames", o.saveFrames, "Write every frame to DIR/frame-0000.png, frame-0001.png, ...")->type_name("DIR")->group(g);
  CLI::Option* videoQuality =
      app.add_option("--video-quality", o.videoQuality,
                     "--video: constant quality, 0 (lossless) to 51, lower is better and larger (default 16: hatching without visible loss)")
          ->type_name("0..51")->group(g);
  app.add_option("--frame-range", frameRange,
                 "Render only frames FIRST-LAST of the sequence (numbered from 0 as --save-frames names them), the same pixels as in "
                 "the whole run: split a sequence over machines (docs/video.md)")
      ->type_name("FIRST-LAST")->group(g);
  app.add_option("--svg", o.svg, "Write the last frame's visible feature lines to FILE as SVG (needs --lines; the overlay has a button too)")
      ->type_name("FILE")->group(g);
  app.add_flag("--svg-raster", o.svgRaster, "--svg: embed the rendered frame under the lines")->group(g);
  app.add_flag("--svg-fill", o.svgFill,
               "--svg: the shaded picture as vector regions too, each palette entry's filled with its texture as an SVG pattern, over the background")
      ->group(g);
  app.add_option("--tile", o.tile, "Render the headless still in N x N pixel tiles (posters larger than the GL allows tile themselves)")
      ->type_name("N")->group(g);

  g = group("Palette tools");
  app.add_option("--make-palette", o.makePalette,
                 "Make a palette from IMAGE (with --ladder) or from a stroke image (with --tam), write it to --out DIR and print its report")
      ->type_name("IMAGE")->group(g);
  app.add_option("--ladder", ladder, "--make-palette step applied progressively: blur|offset|solarize|posterize|threshold|darken|desaturate")
      ->type_name("STEP")->group(g);
  app.add_flag("--tam", o.tam, "--make-palette: draw a tonal art map with IMAGE as the stroke")->group(g);
  app.add_option("--levels", o.levels, "--make-palette: palette entries, 2..256 (default 10)")->type_name("N")->group(g);
  CLI::Option* out = app.add_option("--out", o.outDir, "Output folder: --make-palette's, or the benchmark's (default benchmark-results)")
                         ->type_name("DIR")->group(g);
  app.add_option("--palette-info", o.paletteInfo, "Print a palette's report as one line of JSON and exit")->type_name("FILE")->group(g);
  app.add_option("--palette-sheet", o.paletteSheet,
                 "Write a contact sheet PNG per palette (--palette, or every palette in palettes/) to DIR: levels, tones, a lit sphere")
      ->type_name("DIR")->group(g);

  g = group("Diagnostics");
  app.add_flag("--info", o.info, "Print each file's load report and scene (objects, cameras, lights, animations) as one line of JSON and exit")
      ->group(g);
  app.add_option("--gpu", gpu,
                 "Headless runs: the EGL device, by index or part of its name, 'auto' (a GPU before a software rasterizer) "
                 "or 'surfaceless' (Mesa's software platform); --gl-info lists them")
      ->envname("NPR_GPU")->type_name("DEVICE")->group(g);
  app.add_flag("--verbose", o.verbose,
               "Say every warning of a load (otherwise the first three of each kind, then how many more); bypasses the mesh cache")
      ->group(g);
  app.add_flag("--gl-info", o.glInfo, "Print the headless context's GL_VENDOR, GL_RENDERER, GL_VERSION and the EGL devices, and exit")->group(g);
  app.add_flag("--list-paths", o.listPaths, "Print every render path (name, user or internal, description) and exit")->group(g);
  app.add_flag("--benchmark", o.benchmark, "Headless speed/accuracy benchmark of every path (models may be generated:torus-871k)")->group(g);
  app.add_flag("--settings-reference", o.settingsReference, "Print the settings reference (the README's section) and exit")->group(g);
  app.add_flag("--man-page", manPageWanted, "Print the manual page (roff, generated from these options) and exit")->group(g);
  app.add_flag("--naive-stencil", naiveStencil,
               "Stencil path: mask and full-screen quads bucket by bucket, for every bucket (the original's cost; "
               "--no-stencil-scissor --no-stencil-skip-empty --no-stencil-masks-first)")
      ->group(g);

  // The settings: one option per row of the table, in its sections.
  std::map<const Setting*, std::string> given;  // the row's value as the command line gave it
  std::map<const Setting*, CLI::Option*> options;
  const Look defaults;
  for (const SettingSection& section : settingSections())
    for (const Setting& row : settingsTable()) {
      if (row.section != section.name || !row.cli) continue;
      const std::string help = row.help + " (" + row.valueForm() + "; default " + row.format(defaults) + ")";
      const Setting* r = &row;
      const std::string sectionGroup = group(section.title.c_str());
      CLI::Option* opt = nullptr;
      if (row.type == SettingType::Bool && !row.cliTakesValue) {
        // --key and --no-key; the help names the pair on one line.
        const std::string flagHelp = row.help + " (default " + row.format(defaults) + "; --no-" + row.key + " turns it off)";
        opt = app.add_flag_function("--" + row.key, [&given, r](std::int64_t) { given[r] = "on"; }, flagHelp);
        app.add_flag_function("--no-" + row.key, [&given, r](std::int64_t) { given[r] = "off"; }, "")->group("");
      } else if (row.repeated) {
        // Each occurrence adds an item (setting.h: repeated).
        opt = app.add_option_function<std::vector<std::string>>("--" + row.key, [&given, r](const std::vector<std::string>& items) {
          for (const std::string& v : items) given[r] += (given[r].empty() ? "" : "\n") + v;
        }, help);
        opt->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)->allow_extra_args(false);
      } else {
        opt = app.add_option_function<std::string>("--" + row.key, [&given, r](const std::string& v) { given[r] = v; }, help);
      }
      if (!(row.type == SettingType::Bool && !row.cliTakesValue)) opt->type_name(row.typeName());
      opt->group(sectionGroup);
      options[r] = opt;
      for (const auto& [alias, value] : row.cliAliases)
        app.add_flag_function(alias, [&given, r, value = value](std::int64_t) { given[r] = value; }, "Same as --" + row.key + " " + value)
            ->group(sectionGroup);
    }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    std::printf("%s", app.help().c_str());
    return {std::nullopt, 0};
  } catch (const CLI::ParseError& e) {
    if (helpAll) {  // a bad argument beside --help-all does not hide the help asked for
      std::printf("%s", app.help().c_str());
      return {std::nullopt, 0};
    }
    return {std::nullopt, fail(e.what())};
  }
  if (helpAll) {
    std::printf("%s", app.help().c_str());
    return {std::nullopt, 0};
  }
  if (manPageWanted) {
    std::printf("%s", manPage(app).c_str());
    return {std::nullopt, 0};
  }
  if (naiveStencil)
    for (const char* key : {"stencil-scissor", "stencil-skip-empty", "stencil-masks-first"}) given[findSetting(key)] = "off";
  // Every value is checked here, so that a bad one stops before anything loads.
  Look scratch;
  for (const Setting& row : settingsTable()) {
    const auto it = given.find(&row);
    if (it == given.end()) continue;
    std::string value = it->second;
    if (row.key == "match" && value == "all" && o.benchmark) {
      o.allMatchModes = true;
      continue;
    }
    if (row.type == SettingType::File) {
      Result<std::string> found = findPalette(value, ".");
      if (!found) return {std::nullopt, fail("--" + row.key + ": " + found.error())};
      value = *found;
    }
    if (Status s = row.parse(value, scratch); !s) return {std::nullopt, fail("--" + row.key + " '" + printable(value) + "': " + s.error())};
    o.settings.push_back({&row, value, "--" + row.key});
  }
  if (auto g = parseGpuRequest(gpu); g) o.gpu = *g;
  else return {std::nullopt, fail(g.error())};
  if (!ladder.empty()) {
    o.ladder = parseLadder(ladder);
    if (!o.ladder) return {std::nullopt, fail("unknown --ladder '" + ladder + "': use blur, offset, solarize, posterize, threshold, darken or desaturate")};
  }
  if (!o.makePalette.empty()) {
    if (o.tam == o.ladder.has_value()) return {std::nullopt, fail("--make-palette needs either --ladder STEP or --tam")};
    if (out->count() == 0) return {std::nullopt, fail("--make-palette needs --out DIR, the palette folder to write")};
    if (o.levels < kMinMakerLevels || o.levels > kMaxPaletteEntries)
      return {std::nullopt, fail("--levels must be " + std::to_string(kMinMakerLevels) + ".." + std::to_string(kMaxPaletteEntries) + ", got " +
                                     std::to_string(o.levels))};
  } else if (o.ladder || o.tam) {
    return {std::nullopt, fail("--ladder and --tam go with --make-palette IMAGE")};
  }
  if (!animate.empty()) {
    Result<CameraAnimation> a = parseCameraAnimation(animate);
    if (!a) return {std::nullopt, fail(a.error())};
    o.animation = *a;
  }
  if (o.tile != 0 && (o.tile < 64 || o.tile > 16384)) return {std::nullopt, fail("--tile must be 64..16384 pixels, got " + std::to_string(o.tile))};
  if (app.count("--turntable") && o.turntable < 2)
    return {std::nullopt, fail("--turntable must be 2..3600 frames, got " + std::to_string(o.turntable))};
  if (!o.video.empty()) {
    Result<VideoFormat> format = videoFormatOf(o.video);
    if (!format) return {std::nullopt, fail(format.error())};
    if (o.turntable == 0 && o.frames < 1)
      return {std::nullopt, fail("--video needs a sequence: --turntable N, or --frames N with --animate or an animated scene")};
    const std::filesystem::path folder = std::filesystem::path(o.video).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
      return {std::nullopt, fail("--video: the folder '" + printable(folder.string()) + "' does not exist")};
    if (std::filesystem::is_directory(o.video, ec)) return {std::nullopt, fail("--video: '" + printable(o.video) + "' is a folder")};
    o.headless = true;
  }
  if (videoQuality->count() && o.video.empty()) return {std::nullopt, fail("--video-quality goes with --video FILE")};
  if (o.videoQuality < 0 || o.videoQuality > VideoSpec::kMaxQuality)
    return {std::nullopt, fail("--video-quality must be 0..51 (lower is better), got " + std::to_string(o.videoQuality))};
  if (o.turntable != 0) {
    if (o.turntable < 2 || o.turntable > 3600) return {std::nullopt, fail("--turntable must be 2..3600 frames, got " + std::to_string(o.turntable))};
    if (!animate.empty()) return {std::nullopt, fail("--turntable is its own camera motion: leave out --animate")};
    o.headless = true;
    o.frames = o.turntable;
    o.animation.orbitDegrees = 360.0f / float(o.turntable);
    if (o.saveFrames.empty() && o.video.empty()) o.saveFrames = "turntable";
  }
  if (!frameRange.empty()) {
    const int frames = std::max(o.frames, 1);
    if (frames < 2) return {std::nullopt, fail("--frame-range needs a sequence: --turntable N, or --frames N")};
    Result<FrameRange> range = parseFrameRange(frameRange, frames);
    if (!range) return {std::nullopt, fail(range.error())};
    o.frameRange = *range;
    o.headless = true;
  }
  if (!o.saveFrames.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.saveFrames, ec);
    if (ec || !std::filesystem::is_directory(o.saveFrames))
      return {std::nullopt, fail("--save-frames: cannot create the folder '" + o.saveFrames + "'" + (ec ? " (" + ec.message() + ")" : ""))};
  }
  if (!layout.empty()) {
    const std::optional<Layout> l = parseLayout(layout);
    if (!l) return {std::nullopt, fail("--layout must be file, row or grid, got '" + printable(layout) + "'")};
    o.layout = *l;
  }
  if (o.cameraFromFile == 0 || o.cameraFromFile < -1) return {std::nullopt, fail("--camera-from-file counts from 1")};
  if (o.cameraFromFile > 0 && (!animate.empty() || o.turntable != 0 || !camera.empty()))
    return {std::nullopt, fail("--camera-from-file is the file's own still view: leave out --camera, --animate and --turntable")};
  for (const std::string& op : objectPalette) {
    const std::size_t eq = op.rfind('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == op.size())
      return {std::nullopt, fail("--object-palette must be OBJECT=FILE, got '" + printable(op) + "'")};
    Result<std::string> file = findPalette(op.substr(eq + 1), ".");
    if (!file) return {std::nullopt, fail("--object-palette " + printable(op.substr(0, eq)) + ": " + file.error())};
    o.objectPalettes.emplace_back(op.substr(0, eq), *file);
  }
  // NAME=VALUE with VALUE in [0, 1], for --object-detail and --material-detail.
  auto details = [&](const char* flag, const char* what, const std::vector<std::string>& given,
                     std::vector<std::pair<std::string, float>>& into) -> bool {
    for (const std::string& d : given) {
      const std::size_t eq = d.rfind('=');
      char* end = nullptr;
      const float v = eq == std::string::npos ? 0.0f : std::strtof(d.c_str() + eq + 1, &end);
      if (eq == std::string::npos || eq == 0 || eq + 1 == d.size() || *end != '\0' || !(v >= 0.0f && v <= 1.0f)) {
        (void)fail(std::string(flag) + " must be " + what + "=VALUE with VALUE in [0, 1], got '" + printable(d) + "'");
        return false;
      }
      into.emplace_back(d.substr(0, eq), v);
    }
    return true;
  };
  if (!details("--object-detail", "OBJECT", objectDetail, o.objectDetails) ||
      !details("--material-detail", "MATERIAL", materialDetail, o.materialDetails))
    return {std::nullopt, 2};
  for (const std::string& pf : paletteFor) {
    const std::size_t eq = pf.rfind('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == pf.size())
      return {std::nullopt, fail("--palette-for must be MATERIAL=FILE, got '" + pf + "'")};
    Result<std::string> file = findPalette(pf.substr(eq + 1), ".");
    if (!file) return {std::nullopt, fail("--palette-for " + printable(pf.substr(0, eq)) + ": " + file.error())};
    o.materialPalettes.emplace_back(pf.substr(0, eq), *file);
  }
  if (!size.empty()) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 1 || h < 1 || w > 65536 || h > 65536)
      return {std::nullopt, fail("--size must be WxH with 1 <= W, H <= 65536, got '" + size + "'")};
    o.size = {w, h};
  }
  if (!camera.empty()) {
    float v[3];
    if (!parseFloats(camera, 3, v) || v[2] <= 0.0f)
      return {std::nullopt, fail("--camera must be YAW,PITCH,DISTANCE with DISTANCE > 0, got '" + camera + "'")};
    o.camera = glm::vec3(v[0], v[1], v[2]);
  }
  if (o.frames < 0 || (app.count("--frames") && o.frames < 1))
    return {std::nullopt, fail("--frames must be at least 1, got " + std::to_string(o.frames))};
  if (const std::string problem = dataDirectoryProblem(); !problem.empty()) return {std::nullopt, fail(problem)};
  if (!o.style.empty()) {
    Result<std::string> style = findStyle(o.style);
    if (!style) return {std::nullopt, fail("--style: " + style.error())};
    o.style = *style;
  }
  if (!std::isfinite(o.time) || o.time < 0.0 || o.time > 1e6) return {std::nullopt, fail("--time must be 0..1000000 seconds")};
  if (!std::isfinite(o.fps) || o.fps < 1.0 || o.fps > 1000.0) return {std::nullopt, fail("--fps must be 1..1000 frames per second")};
  // --info reports a missing model as a failed load (exit 1), like any other load failure.
  for (const auto& m : o.models)
    if (!o.info && m.rfind("generated:", 0) != 0 && !std::filesystem::exists(m)) return {std::nullopt, fail("model file '" + m + "' does not exist")};
  for (std::string& p : o.palettes) {
    Result<std::string> found = findPalette(p, ".");
    if (!found) return {std::nullopt, fail("--palette: " + found.error())};
    p = *found;
  }
  if (!o.paletteInfo.empty() && !std::filesystem::exists(o.paletteInfo))
    return {std::nullopt, fail("palette file '" + o.paletteInfo + "' does not exist")};
  return {o, 0};
}

void tellUser(const std::string& message) { std::fprintf(stderr, "npr-viewer: %s\n", printableMessage(message).c_str()); }

int reportFailure(const std::string& message) {
  tellUser(message);
  return 1;
}

}  // namespace npr
