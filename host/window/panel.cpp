#include "window/panel.h"

#include <imgui/imgui.h>

namespace vkpt::internal {
namespace {

bool DrawRow(PanelRow& row) {
  switch (row.kind) {
    case PanelRow::Kind::kText: ImGui::TextUnformatted(row.label.c_str()); return false;
    case PanelRow::Kind::kSlider: {
      const ImGuiSliderFlags flags = row.logarithmic ? ImGuiSliderFlags_Logarithmic : 0;
      if (row.integer) {
        int v = int(row.value);
        const bool changed = ImGui::SliderInt(row.label.c_str(), &v, int(row.lo), int(row.hi), "%d", flags);
        row.value = v;
        return changed;
      }
      float v = float(row.value);
      const bool changed = ImGui::SliderFloat(row.label.c_str(), &v, float(row.lo), float(row.hi), "%.3g", flags);
      row.value = v;
      return changed;
    }
    case PanelRow::Kind::kCheckbox: {
      bool on = row.value != 0.0;
      const bool changed = ImGui::Checkbox(row.label.c_str(), &on);
      row.value = on ? 1.0 : 0.0;
      return changed;
    }
    case PanelRow::Kind::kChoice: {
      int index = int(row.value);
      const char* shown = index >= 0 && size_t(index) < row.choices.size() ? row.choices[index].c_str() : "";
      bool changed = false;
      if (ImGui::BeginCombo(row.label.c_str(), shown)) {
        for (size_t i = 0; i < row.choices.size(); ++i)
          if (ImGui::Selectable(row.choices[i].c_str(), int(i) == index)) {
            changed = int(i) != index;
            index = int(i);
          }
        ImGui::EndCombo();
      }
      row.value = index;
      return changed;
    }
    case PanelRow::Kind::kButton: return ImGui::Button(row.label.c_str());
  }
  return false;
}

}  // namespace

void DrawPanel(const std::string& title, std::vector<PanelRow>& rows) {
  ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.8f);
  if (ImGui::Begin(title.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushItemWidth(160.0f);
    for (PanelRow& row : rows)
      row.changed = row.kind == PanelRow::Kind::kText && row.label.empty() ? false : DrawRow(row);
    ImGui::PopItemWidth();
  }
  ImGui::End();
}

}  // namespace vkpt::internal
