// Command-line parsing and validation (see cli.h).
#include "app/cli.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace npr {
namespace {

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
  std::fprintf(stderr, "npr-viewer: %s (see --help)\n", msg.c_str());
  return 2;
}

}  // namespace

ParseOutcome parseCommandLine(int argc, char** argv) {
  CLI::App app{"npr-viewer: palette-based non-photorealistic rendering of meshes.\n"
               "Lights each triangle or pixel with the OpenGL lighting model and shows the palette texture\n"
               "whose average colour or intensity matches best, in screen space."};
  Options o;
  std::string path, match, size, light, camera, rangeScale, lines, tone, bands, materials, outlineMethod;
  float outlineOffset = NAN;
  std::string strokeSize;
  std::vector<std::string> paletteFor;
  std::string animate, pattern, orient, triangleLighting, occlusionMethod;
  float creaseAngle = NAN, lineWidth = NAN;
  app.add_option("model", o.models, "Mesh files (OBJ, PLY, OFF, STL, OM); default models/bunny.obj");
  app.add_option("--palette", o.palettes, "Palette file(s) or palette folders; default palettes/crosshatch");
  app.add_option("--path", path, "Render path: " + userRenderPathNames("|"));
  app.add_flag("--list-paths", o.listPaths, "Print every render path (name, user or internal, description) and exit");
  app.add_option("--match", match, "Match mode: colors|intensity|order (default: the palette's); --benchmark also takes all");
  app.add_option("--range-scale", rangeScale, "IntensityRangeScale S > 0: spreads the palette about its midpoint");
  app.add_option("--size", size, "Framebuffer size WxH (headless) or window size");
  app.add_option("--light", light, "Light position X,Y,Z in model units (the model fits a unit sphere)");
  app.add_option("--camera", camera, "Camera YAW,PITCH,DISTANCE (degrees, degrees, model radii)");
  app.add_flag("--headless", o.headless, "Render through EGL with no window");
  app.add_option("--frames", o.frames, "Render N frames, then exit (benchmark: frames of scripted motion, default 120)");
  app.add_option("--screenshot", o.screenshot, "Write the last frame to FILE (PNG, TGA, EXR, ...)");
  app.add_flag("--info", o.info, "Print the model's load report as one line of JSON and exit");
  app.add_option("--palette-info", o.paletteInfo, "Print a palette's report as one line of JSON and exit");
  app.add_flag("--benchmark", o.benchmark, "Headless speed/accuracy benchmark of every path (models may be generated:torus-871k)");
  CLI::Option* out = app.add_option("--out", o.outDir, "Output folder: the benchmark's (default benchmark-results) or --make-palette's");
  std::string ladder, patternFilter;
  app.add_option("--pattern-filter", patternFilter,
                 "Scaled or anchored patterns: nearest (the nearest texel, default) | linear (bilinear in linear light: smoother, slower)");
  app.add_option("--make-palette", o.makePalette,
                 "Make a palette from IMAGE (with --ladder) or from a stroke image (with --tam), write it to --out DIR and print its report");
  app.add_option("--ladder", ladder, "--make-palette step applied progressively: blur|offset|solarize|posterize|threshold|darken|desaturate");
  app.add_flag("--tam", o.tam, "--make-palette: draw a tonal art map with IMAGE as the stroke");
  app.add_option("--levels", o.levels, "--make-palette: palette entries, 2..256 (default 10)");
  app.add_option("--style", o.style,
                 "A look from a style file: NAME (palettes/styles/NAME.style: crosshatch, pencil, charcoal, painterly, technical, cel, stipple, woodcut, illustrated) "
                 "or FILE; options given beside it win");
  app.add_option("--palette-sheet", o.paletteSheet,
                 "Write a contact sheet PNG per palette (--palette, or every palette in palettes/) to DIR: levels, tones, a lit sphere");
  app.add_option("--materials", materials, "on|off: light with the model's own materials, vertex colours and texture maps (default on)");
  app.add_option("--palette-for", paletteFor,
                 "MATERIAL=FILE: draw the model's material MATERIAL with its own palette (repeatable; needs --materials on)");
  app.add_option("--pattern", pattern, "Pattern space: screen (fixed to the window, the original) | anchored (follows the object, stays flat) | object (glued to the surface, triplanar)");
  app.add_flag("--pattern-no-rotation", o.patternNoRotation, "Anchored patterns move and scale with the object but stay upright");
  app.add_option("--pattern-scale", o.patternScale,
                 "Size of a palette texel in screen pixels, 0.125..16 (default: the window's content scale, 1 headless)");
  app.add_option("--orient", orient,
                 "Hatching direction: none (the texture's own, default) | curvature (along the surface's form) | light "
                 "(along the light's gradient) | DEGREES (a fixed screen angle)");
  app.add_option("--orient-bins", o.orientBins, "Steps the turn is quantised to over 180 degrees (2..64, default 8)");
  app.add_flag("--strokes", o.strokes, "Painterly brush strokes over the path: particles on the surface, coloured by the palette");
  app.add_option("--stroke-density", o.strokeDensity, "Strokes per unit area of the model fitted to the unit sphere (default 3000)");
  app.add_option("--stroke-budget", o.strokeBudget, "At most this many strokes (default 200000)");
  app.add_option("--stroke-size", strokeSize, "Stroke length x width in pixels, LxW (default 16x6)");
  app.add_flag("--ground", o.ground, "A ground plane under the model, drawn with the same palette and path");
  app.add_flag("--shadows", o.shadows, "Cast shadows from every enabled light (GPU-lit paths: vertex, pixel, smooth, reference)");
  app.add_flag("--occlusion", o.occlusion, "Ambient occlusion baked per vertex on the GPU darkens crevices (GPU-lit paths)");
  app.add_option("--occlusion-strength", o.occlusionStrength, "How much the occlusion darkens, 0..1 (default 1)");
  app.add_option("--occlusion-method", occlusionMethod,
                 "baked (per vertex, once per mesh, default) | screen (per pixel, every frame, from what the frame shows; pixel, smooth and reference paths)");
  app.add_option("--shadow-palette", o.shadowPalette,
                 "Control image: a palette drawn where cast shadows fall, blended in by the shadowed share of the light (needs --shadows)");
  app.add_option("--occlusion-palette", o.occlusionPalette,
                 "Control image: a palette drawn in crevices, blended in by the ambient occlusion (needs --occlusion)");
  app.add_option("--triangle-lighting", triangleLighting,
                 "Per-triangle paths light on the cpu | gpu (read back) | auto (gpu with --shadows, default)");
  app.add_option("--animate", animate,
                 "Move the camera every frame: orbit:DEGREES, pan:DX,DY (pixels), zoom:FACTOR, comma-separated (e.g. orbit:1,zoom:1.01)");
  app.add_option("--save-frames", o.saveFrames, "Write every frame to DIR/frame-0000.png, frame-0001.png, ...");
  app.add_option("--svg", o.svg, "Write the last frame's visible feature lines to FILE as SVG (needs --lines; the overlay has a button too)");
  app.add_flag("--svg-raster", o.svgRaster, "--svg: embed the rendered frame under the lines");
  app.add_option("--tile", o.tile, "Render the headless still in N x N pixel tiles (posters larger than the GL allows tile themselves)");
  app.add_option("--turntable", o.turntable,
                 "Render N frames of one full orbit headless into --save-frames DIR (default turntable/), with DIR/turntable.gif");
  app.add_flag("--gouraud", o.gouraud, "Reference path: per-vertex (Gouraud) instead of per-pixel (Phong) lighting");
  app.add_flag("--naive-stencil", o.naiveStencil, "Stencil path: mask and full-screen quads bucket by bucket, for every bucket (the original's cost)");
  app.add_option("--lines", lines, "Feature lines, comma-separated: silhouette,crease,boundary,image,hardware,rim");
  app.add_option("--outline", outlineMethod, "Hardware outlines (--lines hardware) from back faces: fatten (even widths), offset or edges");
  app.add_option("--outline-offset", outlineOffset, "--outline offset: back faces pulled this fraction of their depth towards the eye (0..0.2, default 0.005)");
  app.add_option("--crease-angle", creaseAngle, "Dihedral angle above which an edge is a crease, degrees (default 60)");
  app.add_option("--line-width", lineWidth, "Line width in pixels (default 2)");
  app.add_flag("--sketchy", o.sketchy, "Draw each line as a few jittered strokes");
  app.add_flag("--line-falloff", o.lineFalloff, "Thinner lines with distance");
  app.add_option("--bands", bands, "Cel band thresholds T1,T2,... on the match query axis [0,3] (one fewer than the palette's tones)");
  app.add_option("--tone", tone, "Lighting model the palette matches against: opengl|gooch|splashback|charcoal");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    std::printf("%s", app.help().c_str());
    return {std::nullopt, 0};
  } catch (const CLI::ParseError& e) {
    return {std::nullopt, fail(e.what())};
  }
  if (!patternFilter.empty()) {
    if (patternFilter != "nearest" && patternFilter != "linear")
      return {std::nullopt, fail("unknown --pattern-filter '" + patternFilter + "': use nearest or linear")};
    o.patternLinear = patternFilter == "linear";
  }
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
  if (!path.empty()) {
    o.path = parseRenderPath(path);
    if (!o.path || !pathInfo(*o.path).userSelectable)
      return {std::nullopt, fail("unknown --path '" + path + "': use one of " + userRenderPathNames())};
  }
  if (!match.empty() && match == "all" && o.benchmark) {
    o.allMatchModes = true;
  } else if (!match.empty()) {
    o.match = parseMatchMode(match);
    if (!o.match) return {std::nullopt, fail("unknown --match '" + match + "': use colors, intensity or order")};
  }
  if (!materials.empty()) {
    if (materials != "on" && materials != "off") return {std::nullopt, fail("--materials must be on or off, got '" + materials + "'")};
    o.materials = materials == "on";
  }
  if (!pattern.empty()) {
    o.pattern = parsePatternSpace(pattern);
    if (!o.pattern) return {std::nullopt, fail("unknown --pattern '" + pattern + "': use screen, anchored or object")};
  }
  if (o.patternScale && !(*o.patternScale >= RenderSettings::kMinPatternScale && *o.patternScale <= RenderSettings::kMaxPatternScale))
    return {std::nullopt, fail("--pattern-scale must be in 0.125..16 (texel size in pixels), got " + std::to_string(*o.patternScale))};
  if (!orient.empty()) {
    o.orient = parseOrient(orient);
    if (!o.orient) return {std::nullopt, fail("unknown --orient '" + orient + "': use none, curvature, light or an angle in degrees")};
  }
  if (o.orientBins && (*o.orientBins < OrientSettings::kMinBins || *o.orientBins > OrientSettings::kMaxBins))
    return {std::nullopt, fail("--orient-bins must be " + std::to_string(OrientSettings::kMinBins) + ".." +
                                   std::to_string(OrientSettings::kMaxBins) + ", got " + std::to_string(*o.orientBins))};
  if (!occlusionMethod.empty()) {
    if (occlusionMethod == "baked") o.occlusionMethod = OcclusionMethod::Baked;
    else if (occlusionMethod == "screen") o.occlusionMethod = OcclusionMethod::Screen;
    else return {std::nullopt, fail("unknown --occlusion-method '" + occlusionMethod + "': use baked or screen")};
  }
  if (!triangleLighting.empty()) {
    if (triangleLighting == "cpu") o.triangleLighting = TriangleLighting::Cpu;
    else if (triangleLighting == "gpu") o.triangleLighting = TriangleLighting::Gpu;
    else if (triangleLighting == "auto") o.triangleLighting = TriangleLighting::Auto;
    else return {std::nullopt, fail("unknown --triangle-lighting '" + triangleLighting + "': use cpu, gpu or auto")};
  }
  if (o.strokeDensity && !(*o.strokeDensity >= StrokeSettings::kMinDensity && *o.strokeDensity <= StrokeSettings::kMaxDensity))
    return {std::nullopt, fail("--stroke-density must be in 1..1000000 strokes per unit area")};
  if (o.strokeBudget && !(*o.strokeBudget >= 0 && *o.strokeBudget <= StrokeSettings::kMaxBudget))
    return {std::nullopt, fail("--stroke-budget must be in 0..4000000")};
  if (!strokeSize.empty() && !(o.strokeSize = parseStrokeSize(strokeSize)))
    return {std::nullopt, fail("--stroke-size must be LxW in pixels, each 1..256, got '" + strokeSize + "'")};
  if (o.occlusionStrength && !(*o.occlusionStrength >= 0.0f && *o.occlusionStrength <= 1.0f))
    return {std::nullopt, fail("--occlusion-strength must be in 0..1, got " + std::to_string(*o.occlusionStrength))};
  if (!animate.empty()) {
    Result<CameraAnimation> a = parseCameraAnimation(animate);
    if (!a) return {std::nullopt, fail(a.error())};
    o.animation = *a;
  }
  if (o.tile != 0 && (o.tile < 64 || o.tile > 16384)) return {std::nullopt, fail("--tile must be 64..16384 pixels, got " + std::to_string(o.tile))};
  if (o.turntable != 0) {
    if (o.turntable < 2 || o.turntable > 3600) return {std::nullopt, fail("--turntable must be 2..3600 frames, got " + std::to_string(o.turntable))};
    if (!animate.empty()) return {std::nullopt, fail("--turntable is its own camera motion: leave out --animate")};
    o.headless = true;
    o.frames = o.turntable;
    o.animation.orbitDegrees = 360.0f / float(o.turntable);
    if (o.saveFrames.empty()) o.saveFrames = "turntable";
  }
  if (!o.saveFrames.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.saveFrames, ec);
    if (ec || !std::filesystem::is_directory(o.saveFrames))
      return {std::nullopt, fail("--save-frames: cannot create the folder '" + o.saveFrames + "'" + (ec ? " (" + ec.message() + ")" : ""))};
  }
  for (const auto& [option, file] : {std::pair{"--shadow-palette", &o.shadowPalette}, std::pair{"--occlusion-palette", &o.occlusionPalette}})
    if (!file->empty() && !std::filesystem::exists(*file))
      return {std::nullopt, fail(std::string(option) + ": palette file '" + *file + "' does not exist")};
  for (const std::string& pf : paletteFor) {
    const std::size_t eq = pf.rfind('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == pf.size())
      return {std::nullopt, fail("--palette-for must be MATERIAL=FILE, got '" + pf + "'")};
    const std::string file = pf.substr(eq + 1);
    if (!std::filesystem::exists(file)) return {std::nullopt, fail("--palette-for " + pf.substr(0, eq) + ": palette file '" + file + "' does not exist")};
    o.materialPalettes.emplace_back(pf.substr(0, eq), file);
  }
  if (!rangeScale.empty()) {
    char* end = nullptr;
    const float s = std::strtof(rangeScale.c_str(), &end);
    if (*end != '\0' || !std::isfinite(s) || s <= 0.0f) return {std::nullopt, fail("--range-scale must be a finite number > 0, got '" + rangeScale + "'")};
    o.rangeScale = s;
  }
  if (!size.empty()) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 1 || h < 1 || w > 65536 || h > 65536)
      return {std::nullopt, fail("--size must be WxH with 1 <= W, H <= 65536, got '" + size + "'")};
    o.size = {w, h};
  }
  if (!light.empty()) {
    float v[3];
    if (!parseFloats(light, 3, v)) return {std::nullopt, fail("--light must be three finite numbers X,Y,Z, got '" + light + "'")};
    o.light = glm::vec3(v[0], v[1], v[2]);
  }
  if (!camera.empty()) {
    float v[3];
    if (!parseFloats(camera, 3, v) || v[2] <= 0.0f)
      return {std::nullopt, fail("--camera must be YAW,PITCH,DISTANCE with DISTANCE > 0, got '" + camera + "'")};
    o.camera = glm::vec3(v[0], v[1], v[2]);
  }
  if (!lines.empty()) {
    LineSettings kinds;
    std::string unknown;
    if (!parseLineKinds(lines, kinds, &unknown))
      return {std::nullopt, fail("unknown --lines kind '" + unknown + "': use silhouette, crease, boundary, image, hardware or rim")};
    o.lineKinds = kinds;
  }
  if (!outlineMethod.empty() && !(o.outlineMethod = parseOutlineMethod(outlineMethod)))
    return {std::nullopt, fail("unknown --outline '" + outlineMethod + "': use fatten, offset or edges")};
  if (!std::isnan(outlineOffset)) {
    if (!(outlineOffset >= LineSettings::kMinOutlineOffset && outlineOffset <= LineSettings::kMaxOutlineOffset))
      return {std::nullopt, fail("--outline-offset must be in [0, 0.2]")};
    o.outlineOffset = outlineOffset;
  }
  if (!std::isnan(creaseAngle)) {
    if (!(creaseAngle >= 0.0f && creaseAngle <= 180.0f)) return {std::nullopt, fail("--crease-angle must be in [0, 180]")};
    o.creaseAngle = creaseAngle;
  }
  if (!std::isnan(lineWidth)) {
    if (!(lineWidth > 0.0f && lineWidth <= 64.0f)) return {std::nullopt, fail("--line-width must be in (0, 64] pixels")};
    o.lineWidth = lineWidth;
  }
  if (!bands.empty()) {
    std::stringstream ss(bands);
    std::string part;
    while (std::getline(ss, part, ',')) {
      char* end = nullptr;
      const float t = std::strtof(part.c_str(), &end);
      if (part.empty() || *end != '\0' || !std::isfinite(t) || (!o.bands.empty() && t <= o.bands.back()))
        return {std::nullopt, fail("--bands must be finite, strictly ascending numbers, got '" + bands + "'")};
      o.bands.push_back(t);
    }
  }
  if (!tone.empty()) {
    o.tone = parseToneModel(tone);
    if (!o.tone) return {std::nullopt, fail("unknown --tone '" + tone + "': use opengl, gooch, splashback or charcoal")};
  }
  if (o.frames < 0) return {std::nullopt, fail("--frames must be >= 0")};
  // --info reports a missing model as a failed load (exit 1), like any other load failure.
  for (const auto& m : o.models)
    if (!o.info && m.rfind("generated:", 0) != 0 && !std::filesystem::exists(m)) return {std::nullopt, fail("model file '" + m + "' does not exist")};
  for (const auto& p : o.palettes)
    if (!std::filesystem::exists(p)) return {std::nullopt, fail("palette file '" + p + "' does not exist")};
  if (!o.paletteInfo.empty() && !std::filesystem::exists(o.paletteInfo))
    return {std::nullopt, fail("palette file '" + o.paletteInfo + "' does not exist")};
  return {o, 0};
}

int reportFailure(const std::string& message) {
  std::fprintf(stderr, "npr-viewer: %s\n", message.c_str());
  return 1;
}

}  // namespace npr
