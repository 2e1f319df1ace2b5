// The export dialog and its progress (see export_dialog.h).
#include "app/window/export_dialog.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>

#include "app/next_free_name.h"
#include "app/window/glfw_window.h"
#include "renderer/core/printable.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

// What the dialog keeps between openings: the kind, the size, the frames, the path typed.
struct ExportForm {
  int kind = 0;  // 0 picture, 1 lines, 2 turntable
  int width = 0, height = 0, frames = 120;
  std::array<char, 1024> path{};
  bool confirmReplace = false;
  bool wantFocus = false;
};
ExportForm form;

const char* const kKinds[] = {"Picture", "Lines (SVG)", "Turntable"};
const char* const kStems[] = {"npr-picture", "npr-lines", "npr-turntable"};
const char* const kExtensions[] = {".png", ".svg", ".mp4"};

void suggestName(const Viewer& v) {
  const fs::path name = nextFreeName(v.screenshotDir, kStems[form.kind], kExtensions[form.kind]);
  std::snprintf(form.path.data(), form.path.size(), "%s", name.string().c_str());
  form.confirmReplace = false;
}

// Each window frame gives the export this long: the window redraws its progress between.
constexpr double kStepBudgetMs = 40.0;

}  // namespace

void cancelExport(Viewer& v) {
  if (!v.exportJob) return;
  const std::string path = v.exportJob->request().path;
  v.exportJob.reset();
  v.renderer->resetPattern();
  v.state.note("export cancelled: nothing written to " + path);
}

void stepExport(Viewer& v) {
  if (!v.exportJob) return;
  Result<bool> done = v.exportJob->step(v.state, *v.renderer, kStepBudgetMs);
  if (done && !*done) return;
  const std::string path = v.exportJob->request().path;
  v.exportJob.reset();
  // The export's frames moved the anchored pattern: the window's view starts it again.
  v.renderer->resetPattern();
  if (done) v.state.note("exported " + path);
  else v.state.problem("export failed: " + done.error());
}

void drawExportDialog(Viewer& v) {
  if (v.exportJob) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.4f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(480.0f * ImGui::GetFontSize() / ImGuiSession::kFontPixels, display.x * 0.9f), 0.0f), ImGuiCond_Always);
    ImGui::Begin("Exporting", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(printable(v.exportJob->label()).c_str());
    ImGui::ProgressBar(float(v.exportJob->fraction()), ImVec2(-1.0f, 0.0f));
    const bool cancel = ImGui::Button("Cancel (Esc)");
    ImGui::End();
    if (cancel) cancelExport(v);
    return;
  }
  if (v.dialog != Viewer::Dialog::Export) return;
  if (v.dialogJustOpened) {
    const glm::ivec4 scene = v.sceneViewport();
    if (form.width == 0) form.width = std::max(16, scene.z), form.height = std::max(16, scene.w);
    suggestName(v);
    form.wantFocus = true;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.3f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(640.0f * ImGui::GetFontSize() / ImGuiSession::kFontPixels, display.x * 0.9f), 0.0f), ImGuiCond_Always);
  bool open = true;
  if (!ImGui::Begin("Export (Ctrl+E)", &open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    if (!open) v.dialog = Viewer::Dialog::None;
    return;
  }
  for (int k = 0; k < 3; ++k) {
    if (k) ImGui::SameLine();
    if (ImGui::RadioButton(kKinds[k], form.kind == k)) form.kind = k, suggestName(v);
  }
  ImGui::TextWrapped("The file's extension decides: .png .jpg .exr a picture, .svg the lines, .mp4 .webm .gif a turntable of the view");
  ImGui::PushItemWidth(-1.0f);
  if (form.wantFocus) ImGui::SetKeyboardFocusHere();
  bool go = ImGui::InputText("##exportpath", form.path.data(), form.path.size(), ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll) ||
            v.dialogEnter;
  v.dialogEnter = false;
  if (ImGui::IsItemActive()) form.wantFocus = false;
  if (ImGui::IsItemEdited()) form.confirmReplace = false;
  ImGui::PopItemWidth();
  const ExportKind kind = exportKindOf(form.path.data());
  ImGui::PushItemWidth(120.0f);
  ImGui::InputInt("width", &form.width, 16, 256);
  ImGui::SameLine();
  ImGui::InputInt("height", &form.height, 16, 256);
  if (kind == ExportKind::Turntable) {
    ImGui::SameLine();
    ImGui::InputInt("frames (one orbit, 30 a second)", &form.frames, 10, 60);
  }
  ImGui::PopItemWidth();
  std::error_code ec;
  const bool exists = fs::exists(form.path.data(), ec);
  if (form.confirmReplace) {
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s exists. Replace it?", printable(form.path.data()).c_str());
    go = ImGui::Button("Replace");
    ImGui::SameLine();
    if (ImGui::Button("Keep it")) form.confirmReplace = false;
  } else {
    if (ImGui::Button("Export")) go = true;
    if (go && exists) {
      form.confirmReplace = true;  // never replaced without a second, explicit yes
      go = false;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel (Esc)")) v.dialog = Viewer::Dialog::None;
  ImGui::End();
  if (!open) v.dialog = Viewer::Dialog::None;
  if (!go) return;
  v.dialog = Viewer::Dialog::None;
  form.confirmReplace = false;
  Result<std::unique_ptr<ExportJob>> job = ExportJob::start({form.path.data(), {form.width, form.height}, form.frames, 30.0}, v.state);
  if (!job) {
    v.state.problem("not exported: " + job.error());
    return;
  }
  v.exportJob = std::move(*job);
}

}  // namespace npr
