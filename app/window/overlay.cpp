// The Dear ImGui overlay (see overlay.h).
#include "app/window/overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/style_file.h"

namespace npr {
namespace fs = std::filesystem;

void drawOverlay(Viewer& v) {
  ViewerState& s = v.state;
  const FrameStats& st = v.renderer->stats();
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("npr-viewer (F1)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("%.2f ms mean, %.2f ms 1%% worst, %.0f fps", v.timer.meanMs(), v.timer.worst1PercentMs(), v.timer.fps());
  const auto& h = v.timer.history();
  if (!h.empty()) ImGui::PlotLines("##frametimes", h.data(), int(h.size()), 0, "frame ms", 0.0f, 50.0f, ImVec2(300, 50));
  if (s.settings.pattern == PatternSpace::Anchored)
    ImGui::Text("pattern fit: %.3f ms, %d samples", st.cpuPatternMs, st.patternSamples);
  ImGui::Text("CPU: shading %.2f ms, frame %.2f ms   GPU: %s", st.cpuShadingMs, st.cpuFrameMs,
              st.gpuMs >= 0 ? (std::to_string(st.gpuMs).substr(0, 5) + " ms").c_str() : "n/a");
  ImGui::Text("%zu triangles, %d non-empty buckets%s", s.mesh ? s.mesh->triangleCount() : 0, st.nonEmptyBuckets,
              st.backFacesCulled ? ", closed: back faces dropped" : "");
  ImGui::Text("recomputes %d, uploads %d, shader builds %d", st.lightingRecomputes, st.bufferUploads, st.shaderBuilds);
  if (st.lines) ImGui::Text("%d lines, silhouettes %.2f ms", st.lines, st.cpuLinesMs);
  if (st.surfaceBuffers) ImGui::Text("stencil surface buffers %d, %d by a pass of their own", st.surfaceBuffers, st.surfaceBufferPasses);
  ImGui::Separator();
  ImGui::Text("model: %s", s.mesh ? fs::path(s.mesh->report.file).filename().c_str() : "-");
  // Styles: a whole look at once (app/style_file.h); a style that fails changes nothing.
  if (ImGui::BeginCombo("style", "choose a style")) {
    for (const std::string& file : discoverStyles())
      if (ImGui::Selectable(fs::path(file).stem().c_str())) {
        Result<Style> style = loadStyle(file);
        if (!style) s.note("style not applied: " + style.error());
        else if (Status st2 = applyStyle(*style, s, *v.renderer); !st2) s.note("style not applied: " + st2.error());
      }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("save style")) {
    const fs::path file = v.screenshotDir / ("npr-style-" + std::to_string(++v.styleCount) + ".style");
    std::ofstream out(file);
    out << styleText(s, *v.renderer, "Saved style " + std::to_string(v.styleCount));
    s.note(out.flush() ? "style written to " + file.string() : "cannot write " + file.string());
  }
  // Palette list: the number keys and [ ] choose among these.
  const std::string current = s.palette ? s.palette->name : "-";
  if (ImGui::BeginCombo("palette", current.c_str())) {
    for (int i = 0; i < static_cast<int>(s.palettes.size()); ++i) {
      const std::string label = std::to_string(i + 1) + ": " + fs::path(s.palettes[static_cast<size_t>(i)]).stem().string();
      if (ImGui::Selectable(label.c_str(), i == s.paletteIndex)) applyAction(v, {Action::SelectPalette, i});
    }
    ImGui::EndCombo();
  }
  int mode = static_cast<int>(s.settings.match);
  if (ImGui::Combo("match (M)", &mode, "colors\0intensity\0order\0")) {
    s.settings.match = static_cast<MatchMode>(mode);
    s.settings.bands.clear();  // thresholds live on the previous mode's query axis
  }
  ImGui::SliderFloat("range scale (+/-)", &s.settings.rangeScale, 0.05f, 20.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
  s.settings.rangeScale = std::clamp(std::isfinite(s.settings.rangeScale) ? s.settings.rangeScale : 1.0f, 0.01f, 100.0f);
  const auto& paths = userRenderPaths();
  int pathIndex = int(std::find(paths.begin(), paths.end(), s.settings.path) - paths.begin());
  auto pathLabel = [](void* data, int i, const char** out) {
    *out = pathInfo((*static_cast<const std::vector<RenderPath>*>(data))[static_cast<size_t>(i)]).label;
    return true;
  };
  if (ImGui::Combo("path (P)", &pathIndex, pathLabel, const_cast<std::vector<RenderPath>*>(&paths), int(paths.size())))
    s.settings.path = paths[static_cast<size_t>(pathIndex)];
  if (s.settings.path == RenderPath::Stencil) {
    ImGui::Checkbox("scissor buckets", &s.settings.stencilScissor);
    ImGui::SameLine();
    ImGui::Checkbox("skip empty", &s.settings.stencilSkipEmpty);
    ImGui::SameLine();
    ImGui::Checkbox("masks first", &s.settings.stencilMasksFirst);
  }
  int pattern = static_cast<int>(s.settings.pattern);
  if (ImGui::Combo("pattern (T)", &pattern, "screen\0anchored\0object\0")) {
    s.settings.pattern = static_cast<PatternSpace>(pattern);
    v.renderer->resetPattern();
  }
  if (s.settings.pattern == PatternSpace::Anchored) {
    ImGui::SameLine();
    ImGui::Checkbox("follow rotation", &s.settings.patternFollowsRotation);
  }
  ImGui::SliderFloat("pattern scale", &s.settings.patternScale, RenderSettings::kMinPatternScale, RenderSettings::kMaxPatternScale,
                     "%.2f px/texel", ImGuiSliderFlags_Logarithmic);
  ImGui::Checkbox("smooth pattern (linear filter)", &s.settings.patternLinearFilter);
  // Hatching orientation, and what the palette offers it: entries with a dominant direction.
  OrientSettings& orient = s.settings.orient;
  int source = static_cast<int>(orient.source);
  if (ImGui::Combo("orient strokes", &source, "none (texture's own)\0curvature\0light\0fixed angle\0"))
    orient.source = static_cast<OrientSource>(source);
  if (orient.source == OrientSource::Fixed) ImGui::SliderFloat("stroke angle", &orient.degrees, 0.0f, 180.0f, "%.0f deg");
  if (orient.source != OrientSource::None) ImGui::SliderInt("angle steps", &orient.bins, OrientSettings::kMinBins, 32);
  orient.degrees = std::isfinite(orient.degrees) ? std::clamp(orient.degrees, 0.0f, 180.0f) : 0.0f;
  orient.bins = std::clamp(orient.bins, OrientSettings::kMinBins, OrientSettings::kMaxBins);
  if (s.palette) {
    int oriented = 0;
    for (const PaletteEntry& e : s.palette->entries) oriented += e.orientation.oriented() ? 1 : 0;
    ImGui::Text("%d of %zu entries have a stroke direction", oriented, s.palette->entries.size());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (std::size_t i = 0; i < s.palette->entries.size(); ++i) {
        const TextureOrientation& o = s.palette->entries[i].orientation;
        ImGui::Text("%2zu: %5.1f deg, strength %.2f%s", i, o.degrees, o.strength, o.oriented() ? "" : " (left unrotated)");
      }
      ImGui::EndTooltip();
    }
  }
  if (const DirectionField* field = v.renderer->directionField())
    ImGui::Text("direction field: %zu vertices, %.0f ms", field->weldedVertices, field->ms);
  StrokeSettings& strokes = s.settings.strokes;
  ImGui::Checkbox("brush strokes", &strokes.on);
  if (strokes.on) {
    // Density reseeds the strokes (a fraction of a second on a large mesh): on release only.
    static float pending = -1.0f;
    float density = pending > 0.0f ? pending : strokes.density;
    if (ImGui::SliderFloat("stroke density", &density, 100.0f, 50000.0f, "%.0f / unit area", ImGuiSliderFlags_Logarithmic)) pending = density;
    if (ImGui::IsItemDeactivatedAfterEdit() && pending > 0.0f) {
      strokes.density = std::clamp(pending, StrokeSettings::kMinDensity, StrokeSettings::kMaxDensity);
      pending = -1.0f;
    }
    ImGui::SliderFloat("stroke length", &strokes.length, 2.0f, 64.0f, "%.0f px");
    ImGui::SliderFloat("stroke width", &strokes.width, 1.0f, 32.0f, "%.0f px");
    ImGui::Text("%zu strokes (seeded in %.0f ms)", v.renderer->strokeCount(), v.renderer->strokeSeedMs());
  }
  ImGui::Checkbox("ground plane", &s.settings.ground);
  ImGui::SameLine();
  ImGui::Checkbox("shadows", &s.settings.shadows);
  ImGui::SameLine();
  ImGui::Checkbox("occlusion", &s.settings.occlusion);
  if (s.settings.occlusion) {
    ImGui::SliderFloat("occlusion strength", &s.settings.occlusionStrength, 0.0f, 1.0f);
    s.settings.occlusionStrength = std::isfinite(s.settings.occlusionStrength) ? std::clamp(s.settings.occlusionStrength, 0.0f, 1.0f) : 1.0f;
    int method = static_cast<int>(s.settings.occlusionMethod);
    if (ImGui::Combo("occlusion from", &method, "bake (per vertex, once)\0screen (per pixel, every frame)\0"))
      s.settings.occlusionMethod = static_cast<OcclusionMethod>(method);
    if (s.settings.occlusionMethod == OcclusionMethod::Screen) {
      ImGui::SliderFloat("occlusion reach", &s.settings.screenOcclusionRadius, 0.05f, 1.0f, "%.2f radii");
    } else if (const OcclusionBake* bake = v.renderer->occlusionBake()) {
      if (!bake->done()) ImGui::ProgressBar(float(bake->directionsDone()) / float(bake->directions()), ImVec2(200, 0), "baking occlusion");
      else ImGui::Text("occlusion baked: %d directions, %.0f ms", bake->directions(), bake->ms());
    }
  }
  // Control-image palettes: drawn where shadows fall and in crevices (seed 003).
  if ((s.settings.shadows || s.settings.occlusion) && ImGui::CollapsingHeader("Control palettes")) {
    auto choose = [&](const char* label, ControlParameter parameter, const std::string& current) {
      if (!ImGui::BeginCombo(label, current.empty() ? "(none)" : std::filesystem::path(current).stem().string().c_str())) return;
      if (ImGui::Selectable("(none)", current.empty())) (void)s.setControlPalette(parameter, "", *v.renderer);
      for (const std::string& p : s.palettes)
        if (ImGui::Selectable(std::filesystem::path(p).stem().string().c_str(), current == p)) (void)s.setControlPalette(parameter, p, *v.renderer);
      ImGui::EndCombo();
    };
    ImGui::Checkbox("draw control palettes", &s.settings.controlPalettes);
    if (s.settings.shadows) choose("in shadow", ControlParameter::Shadow, s.shadowPalette);
    if (s.settings.occlusion) choose("in crevices", ControlParameter::Occlusion, s.occlusionPalette);
  }
  if (s.settings.path == RenderPath::Triangle || s.settings.path == RenderPath::Stencil) {
    int where = static_cast<int>(s.settings.triangleLighting);
    if (ImGui::Combo("triangle lighting", &where, "auto (GPU with shadows)\0CPU\0GPU (read back)\0"))
      s.settings.triangleLighting = static_cast<TriangleLighting>(where);
  }
  ImGui::Checkbox("Gouraud reference", &s.settings.referenceGouraud);
  ImGui::Checkbox("Model materials", &s.settings.materials);
  // Per-material palettes: a palette for each of the model's materials.
  if (s.settings.materials && s.mesh && !s.mesh->materials.empty() && ImGui::CollapsingHeader("Material palettes")) {
    const std::size_t shown = std::min<std::size_t>(s.mesh->materials.size(), 64);
    for (std::size_t i = 0; i < shown; ++i) {
      const MeshMaterial& m = s.mesh->materials[i];
      ImGui::PushID(static_cast<int>(i));
      const auto it = s.materialPalettes.find(m.name);
      const std::string current = it == s.materialPalettes.end() ? "(main palette)" : std::filesystem::path(it->second).stem().string();
      if (ImGui::BeginCombo(m.name.c_str(), current.c_str())) {
        if (ImGui::Selectable("(main palette)", it == s.materialPalettes.end())) (void)s.setMaterialPalette(m.name, "", *v.renderer);
        for (const std::string& p : s.palettes)
          if (ImGui::Selectable(std::filesystem::path(p).stem().string().c_str(), it != s.materialPalettes.end() && it->second == p))
            (void)s.setMaterialPalette(m.name, p, *v.renderer);
        ImGui::EndCombo();
      }
      ImGui::PopID();
    }
    if (shown < s.mesh->materials.size()) ImGui::Text("... and %zu more materials", s.mesh->materials.size() - shown);
  }
  if (ImGui::CollapsingHeader("Lines and tone")) {
    LineSettings& ls = s.settings.lines;
    ImGui::Checkbox("silhouettes", &ls.silhouettes);
    ImGui::SameLine();
    ImGui::Checkbox("creases", &ls.creases);
    ImGui::SameLine();
    ImGui::Checkbox("boundaries", &ls.boundaries);
    ImGui::Checkbox("image-space edges", &ls.imageSpace);
    ImGui::SameLine();
    ImGui::Checkbox("hardware outline", &ls.hardware);
    ImGui::SameLine();
    ImGui::Checkbox("charcoal rim", &ls.rim);
    if (ls.hardware) {
      int method = static_cast<int>(ls.outline);
      if (ImGui::Combo("outline method", &method, "edges\0offset\0fatten\0")) ls.outline = static_cast<OutlineMethod>(method);
      if (ls.outline == OutlineMethod::Offset)
        ImGui::SliderFloat("outline offset", &ls.outlineOffset, LineSettings::kMinOutlineOffset, LineSettings::kMaxOutlineOffset, "%.3f");
    }
    ImGui::Checkbox("sketchy", &ls.sketchy);
    ImGui::SameLine();
    ImGui::Checkbox("depth falloff", &ls.depthFalloff);
    ImGui::SliderFloat("crease angle", &ls.creaseAngle, 1.0f, 179.0f, "%.0f deg");
    ImGui::SliderFloat("line width", &ls.width, 0.5f, 12.0f, "%.1f px");
    ImGui::SliderFloat("edge threshold", &ls.imageThreshold, 0.05f, 2.0f, "%.2f");
    ImGui::ColorEdit3("silhouette", &ls.silhouetteColour.x, ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine();
    ImGui::ColorEdit3("crease", &ls.creaseColour.x, ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine();
    ImGui::ColorEdit3("boundary", &ls.boundaryColour.x, ImGuiColorEditFlags_NoInputs);
    // Cel bands: movable thresholds between the palette's tones (2 to 8 of them).
    const PaletteMatcher* matcher = v.renderer->matcher();
    if (matcher && s.settings.match != MatchMode::Colors && matcher->levels().size() >= 2 && matcher->levels().size() <= 8) {
      bool bands = !s.settings.bands.empty();
      if (ImGui::Checkbox("cel bands (thresholds)", &bands)) {
        s.settings.bands.clear();
        const auto& L = matcher->levels();
        if (bands)
          for (size_t i = 0; i + 1 < L.size(); ++i) s.settings.bands.push_back(std::clamp(0.5f * (L[i] + L[i + 1]), 0.0f, 3.0f));
      }
      for (size_t i = 0; i < s.settings.bands.size(); ++i) {
        const float lo = i > 0 ? s.settings.bands[i - 1] + 0.01f : 0.0f;
        const float hi = i + 1 < s.settings.bands.size() ? s.settings.bands[i + 1] - 0.01f : 3.0f;
        ImGui::SliderFloat(("threshold " + std::to_string(i + 1)).c_str(), &s.settings.bands[i], lo, hi, "%.3f");
        s.settings.bands[i] = std::clamp(s.settings.bands[i], lo, hi);
      }
    }
    LightingState& lighting = v.renderer->lighting();
    int tone = static_cast<int>(lighting.toneModel());
    ToneParameters tp = lighting.toneParameters();
    bool changed = ImGui::Combo("tone", &tone, "OpenGL\0Gooch\0splashback\0charcoal\0");
    if (tone == static_cast<int>(ToneModel::Gooch) || tone == static_cast<int>(ToneModel::Splashback)) {  // charcoal has no parameters
      changed |= ImGui::SliderFloat("blue", &tp.blue, 0.0f, 1.0f);
      changed |= ImGui::SliderFloat("yellow", &tp.yellow, 0.0f, 1.0f);
      changed |= ImGui::SliderFloat("alpha", &tp.alpha, 0.0f, 1.0f);
      changed |= ImGui::SliderFloat("beta", &tp.beta, 0.0f, 1.0f);
      if (tone == 2) {
        changed |= ImGui::SliderFloat("splash alpha", &tp.splashAlpha, 0.0f, 1.0f);
        changed |= ImGui::SliderFloat("splash power", &tp.splashPower, 0.0f, 16.0f);
      }
    }
    if (changed) {
      if (Status st = lighting.setToneModel(static_cast<ToneModel>(tone), tp); !st) s.note(st.error());
    }
  }
  ImGui::Checkbox("split view (B)", &s.splitView);
  ImGui::Separator();
  ImGui::DragFloat3("light", &s.light.x, 0.02f);
  if (ImGui::Checkbox("light follows camera (L)", &s.lightFollowsCamera)) {
    s.lightFollowsCamera = !s.lightFollowsCamera;  // undo, then convert through the action
    applyAction(v, {Action::ToggleLightFollow});
  }
  if (ImGui::Button("frame (F)")) applyAction(v, {Action::FrameModel});
  ImGui::SameLine();
  if (ImGui::Button("reset view (R)")) applyAction(v, {Action::ResetView});
  ImGui::SameLine();
  if (ImGui::Button("screenshot (F12)")) applyAction(v, {Action::Screenshot});
  ImGui::SameLine();
  if (ImGui::Button("export lines (SVG)")) v.svgRequested = true;
  ImGui::SameLine();
  bool vsync = v.vsync;
  if (ImGui::Checkbox("vsync (V)", &vsync)) applyAction(v, {Action::ToggleVsync});
  ImGui::Checkbox("help (H)", &v.help);
  ImGui::SameLine();
  if (ImGui::Button("quit (Esc)")) applyAction(v, {Action::Quit});
  if (!s.messages.empty()) {
    ImGui::Separator();
    for (const auto& m : s.messages) ImGui::TextWrapped("%s", m.c_str());
    if (ImGui::Button("clear messages")) s.messages.clear();
  }
  if (v.help) {
    ImGui::Separator();
    for (const Binding& b : keyBindings()) ImGui::BulletText("%s: %s", b.keys, b.what);
  }
  ImGui::End();
}

}  // namespace npr
