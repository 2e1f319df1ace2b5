// Open and save-as dialogs (see file_dialogs.h).
#include "app/window/file_dialogs.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "app/settings/style_file.h"
#include "app/window/glfw_window.h"
#include "app/window/recent_files.h"
#include "renderer/core/printable.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

// The dialogs' text fields: what was typed survives closing and opening again, selected, so
// typing replaces it and the arrow keys edit it.
std::array<char, 1024> openPath{};
std::array<char, 256> styleName{};
bool confirmReplace = false;
bool wantFocus = false;  // the path or name field asks for the keyboard until it has it

// Before the dialog's text field: asks for the keyboard (a window's first frame may skip its
// items, so the request stands until the field is active).
void focusField() {
  if (wantFocus) ImGui::SetKeyboardFocusHere();
}
void fieldDrawn() {
  if (ImGui::IsItemActive()) wantFocus = false;
}

void setText(std::array<char, 1024>& field, const std::string& text) {
  std::snprintf(field.data(), field.size(), "%s", text.c_str());
}

// Centred, sized to its content, and given the keyboard on its first frame.
bool beginDialog(Viewer& v, const char* title) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.3f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(640.0f * ImGui::GetFontSize() / ImGuiSession::kFontPixels, display.x * 0.9f), 0.0f), ImGuiCond_Always);
  bool open = true;
  if (!ImGui::Begin(title, &open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    if (!open) v.dialog = Viewer::Dialog::None;
    return false;
  }
  if (!open) v.dialog = Viewer::Dialog::None;
  return true;
}

// Entries of the typed path's folder that start with what is typed after its last slash.
std::vector<std::string> completions(const std::string& typed) {
  const fs::path p(typed);
  const fs::path dir = typed.empty() || typed.back() == '/' ? fs::path(typed.empty() ? "." : typed) : (p.has_parent_path() ? p.parent_path() : fs::path("."));
  const std::string prefix = typed.empty() || typed.back() == '/' ? std::string() : p.filename().string();
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end && out.size() < 200; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0 || (name[0] == '.' && prefix.empty())) continue;
    out.push_back((typed.empty() ? name : (dir == "." && !p.has_parent_path() ? name : (dir / name).string())) +
                  (it->is_directory(ec) ? "/" : ""));
  }
  std::sort(out.begin(), out.end());
  if (out.size() > 12) out.resize(12);
  return out;
}

void drawOpen(Viewer& v) {
  if (!beginDialog(v, v.dialogAdds ? "Add to the scene (Ctrl+Shift+O)" : "Open (Ctrl+O)")) return;
  ImGui::TextUnformatted("A model or scene (.obj .gltf .glb .ply .off .stl .om), a palette (.palette or its folder) or a style (.style)");
  ImGui::PushItemWidth(-1.0f);
  focusField();
  const bool enter = ImGui::InputText("##path", openPath.data(), openPath.size(), ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll) || v.dialogEnter;
  v.dialogEnter = false;
  fieldDrawn();
  ImGui::PopItemWidth();
  std::string chosen = enter ? std::string(openPath.data()) : std::string();
  // What the folder holds, then the recent files: a click fills the field (a folder) or opens.
  for (const std::string& c : completions(openPath.data()))
    if (ImGui::Selectable(printable(c).c_str())) {
      if (!c.empty() && c.back() == '/') setText(openPath, c), wantFocus = true;
      else chosen = c;
    }
  if (!v.recent.empty()) {
    ImGui::Separator();
    ImGui::TextUnformatted("Recent");
    for (const std::string& r : v.recent)
      if (ImGui::Selectable((printable(r) + "##recent").c_str())) chosen = r;
  }
  if (ImGui::Button("Open")) chosen = openPath.data();
  ImGui::SameLine();
  if (ImGui::Button("Cancel (Esc)")) v.dialog = Viewer::Dialog::None;
  ImGui::End();
  if (chosen.empty()) return;
  v.dialog = Viewer::Dialog::None;
  std::error_code ec;
  if (!fs::exists(chosen, ec)) {
    v.state.problem("not opened: " + chosen + " does not exist");
    return;
  }
  // Recent, kept between runs: only what opened (a typo is not worth keeping), as an absolute
  // path so it opens again from any folder.
  const std::size_t problemsBefore = v.state.problems.size();
  (void)openFile(v, chosen, v.dialogAdds);
  if (v.state.problems.size() == problemsBefore) {
    addRecentFile(v.recent, fs::absolute(chosen, ec).string());
    saveRecentFiles(v.recent);
  }
}

// A file name from a style's name: letters, digits and dashes.
std::string fileStem(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) out += char(std::tolower(static_cast<unsigned char>(c)));
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.empty() ? "my-style" : out;
}

void drawSaveStyle(Viewer& v) {
  if (v.dialogJustOpened) {
    std::snprintf(styleName.data(), styleName.size(), "%s", v.state.styleName.empty() ? "My style" : v.state.styleName.c_str());
    confirmReplace = false;
  }
  if (!beginDialog(v, "Save the look as a style (Ctrl+S)")) return;
  ImGui::PushItemWidth(-1.0f);
  focusField();
  bool save = ImGui::InputText("##name", styleName.data(), styleName.size(), ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll) || v.dialogEnter;
  v.dialogEnter = false;
  const bool edited = ImGui::IsItemEdited();
  fieldDrawn();
  ImGui::PopItemWidth();
  if (edited) confirmReplace = false;
  const fs::path file = v.screenshotDir / (fileStem(styleName.data()) + ".style");
  ImGui::Text("writes %s", printable(file.string()).c_str());
  std::error_code ec;
  const bool exists = fs::exists(file, ec);
  if (confirmReplace) {
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s exists. Replace it?", printable(file.filename().string()).c_str());
    if (ImGui::Button("Replace")) save = true;
    else save = false;
    ImGui::SameLine();
    if (ImGui::Button("Keep it")) confirmReplace = false;
  } else {
    if (ImGui::Button("Save")) save = true;
    if (save && exists) {
      confirmReplace = true;  // never replaced without a second, explicit yes
      save = false;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel (Esc)")) v.dialog = Viewer::Dialog::None;
  ImGui::End();
  if (!save) return;
  v.dialog = Viewer::Dialog::None;
  confirmReplace = false;
  const Status saved = saveStyle(v.state, *v.renderer, styleName.data(), file.string());
  if (saved) v.state.note("style written to " + file.string());
  else v.state.problem("style not saved: " + saved.error());
}

}  // namespace

void drawFileDialogs(Viewer& v) {
  if (v.dialogJustOpened) wantFocus = true, v.dialogEnter = false;
  if (v.dialog == Viewer::Dialog::Open) drawOpen(v);
  else if (v.dialog == Viewer::Dialog::SaveStyle) drawSaveStyle(v);
  v.dialogJustOpened = false;
}

}  // namespace npr
