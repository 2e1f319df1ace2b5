// The message bar (see message_bar.h).
#include "app/window/message_bar.h"

#include <imgui.h>

namespace npr {

void drawMessageBar(Viewer& v) {
  if (v.state.problems.empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = display.x - (v.overlay ? v.panelWidth : 0.0f);
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width > 100.0f ? width : display.x, 0.0f), ImGuiCond_Always);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.45f, 0.08f, 0.06f, 0.92f));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing;
  if (ImGui::Begin("##messages", nullptr, flags)) {
    // Already made printable by ViewerState::problem.
    for (const std::string& m : v.state.problems) ImGui::TextWrapped("%s", m.c_str());
    if (ImGui::Button("Dismiss")) v.state.problems.clear();
  }
  ImGui::End();
  ImGui::PopStyleColor();
}

}  // namespace npr
