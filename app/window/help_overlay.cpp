// The keys over the scene (see help_overlay.h).
#include "app/window/help_overlay.h"

#include <imgui.h>

#include <algorithm>

namespace npr {

void drawHelpOverlay(Viewer& v) {
  if (!v.help) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float sceneWidth = display.x - (v.overlay ? v.panelWidth : 0.0f);
  ImGui::SetNextWindowPos(ImVec2(sceneWidth * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(sceneWidth * 0.95f, 720.0f), 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.88f);
  bool open = true;
  if (ImGui::Begin("Keys (H hides)", &open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
    if (ImGui::BeginTable("##keys", 2, ImGuiTableFlags_RowBg)) {
      ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed);
      ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
      for (const Binding& b : keyBindings()) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(b.keys);
        ImGui::TableSetColumnIndex(1);
        ImGui::TextWrapped("%s", b.what);  // at the column's edge
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
  if (!open) v.help = false;
}

}  // namespace npr
