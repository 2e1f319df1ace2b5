// The Dear ImGui overlay (see overlay.h): a panel docked at the window's right edge. Its
// setting widgets are built from the settings table (app/settings/), one collapsing section
// per feature; a feature's details show while it is on. Edits go through applySettings, the
// same check-then-commit the command line and style files use.
#include "app/window/overlay.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "app/settings/look.h"
#include "app/settings/style_file.h"
#include "app/window/glfw_window.h"
#include "renderer/core/printable.h"
#include "renderer/gl/gl_info.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

// A row of widgets wraps instead of running past the panel's edge (where its text was cut): the
// next widget, `width` wide, goes beside the last one only when it fits in what the line has left.
void besideIfFits(float width) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= right) ImGui::SameLine();
}
// The widest label drawn beside a widget (the settings table's, and the panel's own): widgets
// take what the panel has left after it, so a label is not cut at the panel's edge. Half the
// panel each, as before, cut "tone spread (+/-)" at the default panel of a 640-pixel window.
float labelColumn() {
  static float fontSize = 0.0f, widest = 0.0f;  // measured again only when the font changes
  if (fontSize != ImGui::GetFontSize()) {
    fontSize = ImGui::GetFontSize();
    widest = 0.0f;
    for (const Setting& row : settingsTable())
      if (row.type != SettingType::Bool && row.type != SettingType::Kinds)
        widest = std::max(widest, ImGui::CalcTextSize(row.label.c_str(), nullptr, true).x);
    for (const char* label : {"palette", "style", "speed"}) widest = std::max(widest, ImGui::CalcTextSize(label).x);
  }
  return widest + ImGui::GetStyle().ItemInnerSpacing.x;
}
float buttonWidth(const char* label) { return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x; }
float checkboxWidth(const char* label) {
  return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

void tooltip(const std::string& text) {
  if (ImGui::IsItemHovered() && !text.empty()) ImGui::SetTooltip("%s", text.c_str());
}

// One row's widget, editing `look`; true when the value is to be applied now.
bool settingWidget(const Setting& row, Look& look, const std::vector<std::string>& palettes, std::string* error) {
  ImGui::PushID(row.key.c_str());
  bool changed = false;
  switch (row.type) {
    case SettingType::Bool: changed = ImGui::Checkbox(row.label.c_str(), row.boolRef(look)); break;
    case SettingType::Int: {
      static std::map<const Setting*, int> pending;
      int* value = row.intRef(look);
      if (row.applyOnRelease && pending.count(&row)) *value = pending[&row];
      changed = ImGui::SliderInt(row.label.c_str(), value, int(row.min), int(row.max));
      if (row.applyOnRelease) {
        if (changed) pending[&row] = *value;
        changed = ImGui::IsItemDeactivatedAfterEdit();
        if (changed) pending.erase(&row);
      }
      break;
    }
    case SettingType::Float: {
      static std::map<const Setting*, float> pending;
      float* value = row.floatRef(look);
      if (row.applyOnRelease && pending.count(&row)) *value = pending[&row];
      changed = ImGui::SliderFloat(row.label.c_str(), value, float(row.min), float(row.max), "%.3g",
                                   row.logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
      if (row.applyOnRelease) {
        if (changed) pending[&row] = *value;
        changed = ImGui::IsItemDeactivatedAfterEdit();
        if (changed) pending.erase(&row);
      }
      break;
    }
    case SettingType::Choice:
      if (ImGui::BeginCombo(row.label.c_str(), row.format(look).c_str())) {
        for (const std::string& c : row.choices)
          if (ImGui::Selectable(c.c_str(), c == row.format(look))) changed = bool(row.parse(c, look));
        ImGui::EndCombo();
      }
      break;
    case SettingType::Kinds: {
      const std::string current = "," + row.format(look) + ",";
      std::string next;
      for (std::size_t i = 0; i < row.choices.size(); ++i) {
        bool on = current.find("," + row.choices[i] + ",") != std::string::npos;
        if (i > 0) besideIfFits(checkboxWidth(row.choices[i].c_str()));
        changed |= ImGui::Checkbox(row.choices[i].c_str(), &on);
        if (on) next += (next.empty() ? "" : ",") + row.choices[i];
      }
      if (changed) changed = bool(row.parse(next.empty() ? "none" : next, look));
      break;
    }
    case SettingType::Colour: changed = ImGui::ColorEdit3(row.label.c_str(), &row.vectorRef(look)->x, ImGuiColorEditFlags_NoInputs); break;
    case SettingType::Vector: changed = ImGui::DragFloat3(row.label.c_str(), &row.vectorRef(look)->x, 0.02f); break;
    case SettingType::File: {
      const std::string current = row.format(look);
      if (ImGui::BeginCombo(row.label.c_str(), current == "none" ? "(none)" : fs::path(current).stem().string().c_str())) {
        if (ImGui::Selectable("(none)", current == "none")) changed = bool(row.parse("none", look));
        for (const std::string& p : palettes)
          if (ImGui::Selectable(fs::path(p).stem().string().c_str(), fs::absolute(p).lexically_normal().string() == current))
            changed = bool(row.parse(p, look));
        ImGui::EndCombo();
      }
      break;
    }
    case SettingType::Text: {
      // Typed, applied on Enter; a value that does not parse is said in the messages. A list
      // (line sets) is one item per line: Ctrl+Enter starts a line.
      static std::map<const Setting*, std::array<char, 1024>> buffers;
      static std::map<const Setting*, bool> editing;
      std::array<char, 1024>& buf = buffers[&row];
      if (!editing[&row]) std::snprintf(buf.data(), buf.size(), "%s", row.format(look).c_str());
      const bool entered = row.repeated ? ImGui::InputTextMultiline(row.label.c_str(), buf.data(), buf.size(), ImVec2(0, ImGui::GetTextLineHeight() * 5),
                                                                  ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CtrlEnterForNewLine)
                                        : ImGui::InputText(row.label.c_str(), buf.data(), buf.size(), ImGuiInputTextFlags_EnterReturnsTrue);
      if (entered)
        if (Status parsed = row.parse(buf.data(), look); !parsed) *error = row.key + " '" + printable(buf.data()) + "': " + parsed.error();
      editing[&row] = ImGui::IsItemActive();
      break;
    }
  }
  // The exact term too: the option and style key the label stands for.
  tooltip(row.help + " (" + row.valueForm() + "; --" + row.key + ", style key " + row.key + ")");
  ImGui::PopID();
  return changed;
}

// What a feature shows beside its settings while it is on.
void sectionDetails(const std::string& section, Viewer& v, Look& look) {
  ViewerState& s = v.state;
  if (section == "palette") {
    // Cel bands: movable thresholds between the palette's tones (2 to 8 of them).
    const PaletteMatcher* matcher = v.renderer->palettes().matcher();
    if (matcher && look.render.match != MatchMode::Colors && matcher->levels().size() >= 2 && matcher->levels().size() <= 8) {
      bool bands = !look.render.bands.empty();
      if (ImGui::Checkbox("cel bands (thresholds)", &bands)) {
        look.render.bands.clear();
        const auto& L = matcher->levels();
        if (bands)
          for (size_t i = 0; i + 1 < L.size(); ++i) look.render.bands.push_back(std::clamp(0.5f * (L[i] + L[i + 1]), 0.0f, 3.0f));
      }
      for (size_t i = 0; i < look.render.bands.size(); ++i) {
        const float lo = i > 0 ? look.render.bands[i - 1] + 0.01f : 0.0f;
        const float hi = i + 1 < look.render.bands.size() ? look.render.bands[i + 1] - 0.01f : 3.0f;
        ImGui::SliderFloat(("threshold " + std::to_string(i + 1)).c_str(), &look.render.bands[i], lo, hi, "%.3f");
        look.render.bands[i] = std::clamp(look.render.bands[i], lo, hi);
      }
    }
  } else if (section == "path") {
    // Per-material palettes: a palette for each of the model's materials.
    const std::vector<std::string> materials = s.scene.materialNames(65);
    if (look.render.materials && !materials.empty() && ImGui::TreeNode("Material palettes")) {
      const std::size_t shown = std::min<std::size_t>(materials.size(), 64);
      for (std::size_t i = 0; i < shown; ++i) {
        const std::string& name = materials[i];
        ImGui::PushID(static_cast<int>(i));
        const auto it = s.materialPalettes.find(name);
        const std::string current = it == s.materialPalettes.end() ? "(main palette)" : fs::path(it->second).stem().string();
        if (ImGui::BeginCombo(name.c_str(), current.c_str())) {
          if (ImGui::Selectable("(main palette)", it == s.materialPalettes.end())) (void)s.setMaterialPalette(name, "", *v.renderer);  // clearing cannot fail
          for (const std::string& p : s.palettes)
            if (ImGui::Selectable(fs::path(p).stem().string().c_str(), it != s.materialPalettes.end() && it->second == p))
              if (Status st = s.setMaterialPalette(name, p, *v.renderer); !st) s.problem(st.error());
          ImGui::EndCombo();
        }
        ImGui::PopID();
      }
      if (shown < materials.size()) ImGui::TextWrapped("... and more materials");
      ImGui::TreePop();
    }
  } else if (section == "orientation" && look.render.orient.source != OrientSource::None) {
    if (s.palette) {
      int oriented = 0;
      for (const PaletteEntry& e : s.palette->entries) oriented += e.orientation.oriented() ? 1 : 0;
      ImGui::TextWrapped("%d of %zu entries have a stroke direction", oriented, s.palette->entries.size());
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        for (std::size_t i = 0; i < s.palette->entries.size(); ++i) {
          const TextureOrientation& o = s.palette->entries[i].orientation;
          ImGui::TextWrapped("%2zu: %5.1f deg, strength %.2f%s", i, o.degrees, o.strength, o.oriented() ? "" : " (left unrotated)");
        }
        ImGui::EndTooltip();
      }
    }
    const Model* first = v.renderer->scene().first();
    if (const DirectionField* field = first ? first->directionFieldIfComputed() : nullptr)
      ImGui::TextWrapped("direction field: %zu vertices, %.0f ms", field->weldedVertices, field->ms);
  } else if (section == "pattern" && look.render.pattern == PatternSpace::Anchored) {
    ImGui::TextWrapped("pattern fit: %.3f ms, %d samples", v.renderer->stats().cpuPatternMs, v.renderer->stats().patternSamples);
  } else if (section == "occlusion" && look.render.occlusion && look.render.occlusionMethod == OcclusionMethod::Baked) {
    const Model* first = v.renderer->scene().first();
    if (const OcclusionBake* bake = first ? first->occlusionBake() : nullptr) {
      if (!bake->done()) ImGui::ProgressBar(float(bake->directionsDone()) / float(bake->directions()), ImVec2(200, 0), "baking occlusion");
      else ImGui::TextWrapped("occlusion baked: %d directions, %.0f ms", bake->directions(), bake->ms());
    }
  } else if (section == "strokes" && look.render.strokes.on) {
    ImGui::TextWrapped("%zu strokes (seeded in %.0f ms)", v.renderer->scene().strokeCount(), v.renderer->scene().strokeSeedMs());
  }
}

// The scene's objects: shown or hidden, and each one's own palette (an object in wood grain
// beside one in hatching), with where it sits in the scene.
void drawObjectList(Viewer& v) {
  ViewerState& s = v.state;
  const auto& objects = s.scene.objects();
  if (objects.size() < 2 || !ImGui::TreeNode("Objects")) return;
  // Every object, in a scrolling list whose rows are laid out only where they show (a scene of
  // thousands costs what a dozen rows do).
  const bool detailRow = v.renderer->palettes().main() && v.renderer->palettes().main()->axis().kind == PaletteAxisKind::Detail;
  const float rowHeight = ImGui::GetFrameHeightWithSpacing() * (detailRow ? 2.0f : 1.0f);
  ImGui::BeginChild("object rows", ImVec2(0.0f, rowHeight * float(std::min<std::size_t>(objects.size(), 12)) + ImGui::GetStyle().WindowPadding.y * 2.0f),
                    true);
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(objects.size()), rowHeight);
  while (clipper.Step()) {
    for (std::size_t i = std::size_t(clipper.DisplayStart); i < std::size_t(clipper.DisplayEnd); ++i) {
      const ViewerObject& o = objects[i];
      ImGui::PushID(static_cast<int>(i));
      bool visible = o.visible;
      if (ImGui::Checkbox("##shown", &visible)) s.scene.setVisible(i, visible, *v.renderer);
      ImGui::SameLine();
      const std::string current = o.palette.empty() ? "(main palette)" : fs::path(o.palette).stem().string();
      if (ImGui::BeginCombo(o.name.c_str(), current.c_str())) {
        if (ImGui::Selectable("(main palette)", o.palette.empty())) (void)s.scene.setPalette(i, "", *v.renderer);
        for (const std::string& p : s.palettes)
          if (ImGui::Selectable(fs::path(p).stem().string().c_str(), o.palette == p))
            if (Status st = s.scene.setPalette(i, p, *v.renderer); !st) s.problem("palette of '" + o.name + "' not loaded: " + st.error());
        ImGui::EndCombo();
      }
      const bool hovered = ImGui::IsItemHovered();
      // A palette whose rows go by detail: each object's own value.
      if (detailRow) {
        float detail = o.detail;
        ImGui::SetNextItemWidth(120.0f);
        if (ImGui::SliderFloat("detail", &detail, 0.0f, 1.0f, "%.2f")) s.scene.setDetail(i, detail, *v.renderer);
      }
      if (hovered) {
        const glm::mat4& t = o.placed;
        // Its own fitted tone range, under --tone-range per-object.
        std::string tone;
        if (const Model* m = v.renderer->scene().find(o.id); m && m->toneTarget)
          tone = "; its tone range " + std::to_string(m->toneTarget->x).substr(0, 4) + " to " + std::to_string(m->toneTarget->y).substr(0, 4) +
                 " of 3";
        tooltip(std::to_string(o.mesh->triangleCount()) + " triangles; origin at " + std::to_string(t[3].x).substr(0, 6) + ", " +
                std::to_string(t[3].y).substr(0, 6) + ", " + std::to_string(t[3].z).substr(0, 6) + " (scene radius 1)" + tone);
      }
      ImGui::PopID();
    }
  }
  ImGui::EndChild();
  int layout = static_cast<int>(s.scene.layout());
  if (s.scene.files().size() > 1 && ImGui::Combo("layout", &layout, "file\0row\0grid\0")) {
    s.scene.setLayout(static_cast<Layout>(layout), *v.renderer);
    v.renderer->resetPattern();
  }
  ImGui::TreePop();
}

// The scene files' cameras (looked through until the view is moved) and lights.
void drawFileViews(Viewer& v) {
  ViewerState& s = v.state;
  const std::vector<SceneCamera> cameras = s.scene.cameras();
  if (!cameras.empty()) {
    const std::string current = s.fileCamera ? s.fileCamera->name : "orbit";
    if (ImGui::BeginCombo("camera", current.c_str())) {
      if (ImGui::Selectable("orbit", !s.fileCamera)) s.fileCamera.reset();
      for (std::size_t i = 0; i < cameras.size() && i < 64; ++i) {
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::Selectable(cameras[i].name.c_str(), s.fileCamera && s.fileCamera->name == cameras[i].name))
          (void)s.useFileCamera(static_cast<int>(i) + 1);
        ImGui::PopID();
      }
      ImGui::EndCombo();
    }
  }
  if (!s.scene.lights().empty()) ImGui::Checkbox("the file's lights", &s.fileLights);
}

// The scene's clock: which animation plays, play and pause (space), scrubbing and speed.
void drawTimeline(Viewer& v) {
  ViewerState& s = v.state;
  const std::vector<std::string> names = s.scene.animationNames();
  if (names.empty()) return;
  Playback& p = s.playback;
  const std::string current = p.choice.which == AnimationChoice::Which::All    ? "all"
                              : p.choice.which == AnimationChoice::Which::None ? "none (rest pose)"
                                                                               : names[std::min(p.choice.one, names.size() - 1)];
  if (ImGui::BeginCombo("animation", current.c_str())) {
    if (ImGui::Selectable("all", p.choice.which == AnimationChoice::Which::All)) p.choice = {};
    if (ImGui::Selectable("none (rest pose)", p.choice.which == AnimationChoice::Which::None)) p.choice = {AnimationChoice::Which::None, 0};
    for (std::size_t i = 0; i < names.size() && i < 256; ++i) {
      ImGui::PushID(static_cast<int>(i));
      if (ImGui::Selectable(names[i].c_str(), p.choice == AnimationChoice{AnimationChoice::Which::One, i}))
        p.choice = {AnimationChoice::Which::One, i};
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  const double length = s.animationLength();
  if (ImGui::Button(p.playing ? "pause (space)" : "play (space)")) applyAction(v, {Action::TogglePlay});
  ImGui::SameLine();
  float time = static_cast<float>(p.time);
  if (ImGui::SliderFloat("##time", &time, 0.0f, static_cast<float>(std::max(length, 1e-3)), "%.2f s")) p.time = time;
  float speed = static_cast<float>(p.speed);
  if (ImGui::SliderFloat("speed", &speed, 0.05f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) p.speed = speed;
}

}  // namespace

void drawOverlay(Viewer& v) {
  ViewerState& s = v.state;
  const FrameStats& st = v.renderer->stats();
  // Docked at the right edge, the window's full height; its width is the user's (drag the
  // left edge), and the scene is drawn and framed in the rest of the window.
  // Widths in the overlay's own units: on a screen of content scale 2 its font and widgets are
  // twice the size (ImGuiSession), so the panel is too, or its labels would be cut at its edge.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float ui = ImGui::GetFontSize() / ImGuiSession::kFontPixels;
  ImGui::SetNextWindowPos(ImVec2(display.x, 0.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(std::min(360.0f * ui, display.x * 0.45f), display.y), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(200.0f * ui, display.x), display.y), ImVec2(std::max(200.0f * ui, display.x * 0.7f), display.y));
  if (!ImGui::Begin("npr-viewer (F1 hides)", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings)) {
    v.panelWidth = 0.0f;  // collapsed: the scene takes the whole window
    ImGui::End();
    return;
  }
  v.panelWidth = ImGui::GetWindowWidth();
  // Room for the labels beside the widgets, up to 60% of the panel (the widgets keep the rest).
  ImGui::PushItemWidth(-std::min(labelColumn(), 0.6f * v.panelWidth));
  ImGui::TextWrapped("%.2f ms mean, %.2f ms 1%% worst, %.0f fps", v.timer.meanMs(), v.timer.worst1PercentMs(), v.timer.fps());
  const auto& h = v.timer.history();
  // The panel's whole width (Dear ImGui 1.86 draws a plot given -1 one pixel wide).
  if (!h.empty())
    ImGui::PlotLines("##frametimes", h.data(), int(h.size()), 0, "frame ms (0-50)", 0.0f, 50.0f, ImVec2(ImGui::GetContentRegionAvail().x, 40));
  // Wrapped, not cut at the panel's edge, whatever its width.
  ImGui::TextWrapped("CPU: shading %.2f ms, frame %.2f ms; GPU: %s", st.cpuShadingMs, st.cpuFrameMs,
                     st.gpuMs >= 0 ? (std::to_string(st.gpuMs).substr(0, 5) + " ms").c_str() : "n/a");
  // Buckets are the per-triangle paths' (stencil, triangle); the others count none.
  if (st.nonEmptyBuckets > 0) {
    ImGui::TextWrapped("%zu triangles, %d palette entries in use%s", s.scene.triangles(), st.nonEmptyBuckets,
                       st.backFacesCulled ? "; closed, so back faces are skipped" : "");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("entries in use: the palette's non-empty buckets this frame");
  } else {
    ImGui::TextWrapped("%zu triangles%s", s.scene.triangles(), st.backFacesCulled ? "; closed, so back faces are skipped" : "");
  }
  ImGui::TextWrapped("this frame: lighting redone %d times, %d uploads, %d shaders built", st.lightingRecomputes, st.bufferUploads, st.shaderBuilds);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("lighting recomputes, buffer uploads, shader builds");
  if (const std::optional<glm::vec2> tone = v.renderer->toneRange())
    ImGui::TextWrapped("tone range: lit tones %.2f..%.2f of 0..3 fill the palette (%.2f ms)", tone->x, tone->y, st.cpuToneMs);
  if (st.lines) ImGui::TextWrapped("%d lines (found in %.2f ms)", st.lines, st.cpuLinesMs);
  if (st.surfaceBuffers) ImGui::TextWrapped("stencil path: %d surface buffers, %d drawn in a pass of their own", st.surfaceBuffers, st.surfaceBufferPasses);
  // What renders (the window's context never changes, so it is asked once).
  static const GlInfo gl = currentGlInfo();
  ImGui::TextWrapped("GL: %s, %s%s", gl.renderer.c_str(), gl.version.c_str(), gl.software ? " (software rasterizer)" : "");
  ImGui::Separator();
  ImGui::TextWrapped("model: %s", s.scene.label().c_str());
  drawObjectList(v);
  drawFileViews(v);
  drawTimeline(v);
  // Styles: a whole look at once (app/settings/style_file.h); a style that fails changes nothing.
  // Each with its picture on the scene shown (style_thumbnails.h), drawn one a frame while the
  // menu is open.
  if (ImGui::BeginCombo("style", "choose a style", ImGuiComboFlags_HeightLargest)) {
    v.styleThumbnails.request();
    const ImVec2 picture(float(StyleThumbnails::kWidth) * 0.75f, float(StyleThumbnails::kHeight) * 0.75f);
    for (const std::string& file : discoverStyles()) {
      ImGui::PushID(file.c_str());
      const ImVec2 at = ImGui::GetCursorPos();
      if (ImGui::Selectable("##style", false, 0, ImVec2(0.0f, picture.y))) (void)openFile(v, file, false);  // as Ctrl+O opens a style
      ImGui::SetCursorPos(at);
      if (const std::optional<unsigned> texture = v.styleThumbnails.texture(file))
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(*texture)), picture, ImVec2(0, 1), ImVec2(1, 0));  // GL's rows run up
      else
        ImGui::Dummy(picture);
      ImGui::SameLine();
      ImGui::TextUnformatted(fs::path(file).stem().c_str());
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  besideIfFits(buttonWidth("save style (Ctrl+S)"));
  if (ImGui::Button("save style (Ctrl+S)")) applyAction(v, {Action::SaveStyle});
  if (ImGui::Button("open (Ctrl+O)")) applyAction(v, {Action::Open, 0});
  besideIfFits(buttonWidth("add to scene (Ctrl+Shift+O)"));
  if (ImGui::Button("add to scene (Ctrl+Shift+O)")) applyAction(v, {Action::Open, 1});
  // Palette list: the number keys and [ ] choose among these.
  const std::string current = s.palette ? s.palette->name : "-";
  if (ImGui::BeginCombo("palette", current.c_str())) {
    for (int i = 0; i < static_cast<int>(s.palettes.size()); ++i) {
      const std::string label = std::to_string(i + 1) + ": " + fs::path(s.palettes[static_cast<size_t>(i)]).stem().string();
      if (ImGui::Selectable(label.c_str(), i == s.paletteIndex)) applyAction(v, {Action::SelectPalette, i});
    }
    ImGui::EndCombo();
  }

  // The settings, section by section, edited on a copy of the look and applied as rows.
  Look look = currentLook(s, *v.renderer);
  const Look before = look;
  std::vector<const Setting*> now;  // rows to apply this frame (sliders let go, combos chosen, ...)
  for (const SettingSection& section : settingSections()) {
    if (!ImGui::CollapsingHeader(section.title.c_str(), section.name == "palette" || section.name == "path" ? ImGuiTreeNodeFlags_DefaultOpen : 0))
      continue;
    for (const Setting& row : settingsTable()) {
      if (row.section != section.name || row.key == "palette" || (row.shown && !row.shown(look))) continue;
      std::string error;
      if (settingWidget(row, look, s.palettes, &error)) now.push_back(&row);
      if (!error.empty()) s.note(error);
    }
    sectionDetails(section.name, v, look);
  }
  std::vector<SettingValue> changes;
  for (const Setting& row : settingsTable()) {
    const bool released = std::find(now.begin(), now.end(), &row) != now.end();
    if (row.applyOnRelease && !released) continue;
    const std::string value = row.format(look);
    if (value != row.format(before)) changes.push_back({&row, value, "overlay"});
  }
  // Cel thresholds live on the match mode's query axis: a new mode starts without them.
  if (look.render.match != before.render.match && look.render.bands == before.render.bands)
    changes.push_back({findSetting("bands"), "none", "overlay"});
  if (!changes.empty()) {
    if (Status applied = applySettings(changes, false, s, *v.renderer); !applied) s.problem(applied.error());
    if (look.render.pattern != before.render.pattern) v.renderer->resetPattern();
  }

  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
    bool split = s.splitView;
    if (ImGui::Checkbox("split view (B)", &split)) applyAction(v, {Action::ToggleSplit});  // framed as B frames it
    if (ImGui::Checkbox("light follows camera (L)", &s.lightFollowsCamera)) {
      s.lightFollowsCamera = !s.lightFollowsCamera;  // undo, then convert through the action
      applyAction(v, {Action::ToggleLightFollow});
    }
    if (ImGui::Button("frame (F)")) applyAction(v, {Action::FrameModel});
    besideIfFits(buttonWidth("reset view (R)"));
    if (ImGui::Button("reset view (R)")) applyAction(v, {Action::ResetView});
    besideIfFits(buttonWidth("screenshot (F12)"));
    if (ImGui::Button("screenshot (F12)")) applyAction(v, {Action::Screenshot, 0});
    if (ImGui::Button("export lines (SVG)")) v.svgRequested = true;
    besideIfFits(checkboxWidth("vsync (V)"));
    bool vsync = v.vsync;
    if (ImGui::Checkbox("vsync (V)", &vsync)) applyAction(v, {Action::ToggleVsync});
    ImGui::Checkbox("help (H)", &v.help);
    besideIfFits(buttonWidth("quit (Esc)"));
    if (ImGui::Button("quit (Esc)")) applyAction(v, {Action::Quit});
  }
  if (!s.messages.empty()) {
    ImGui::Separator();
    for (const auto& m : s.messages) ImGui::TextWrapped("%s", m.c_str());
    if (ImGui::Button("clear messages")) s.messages.clear();
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace npr
