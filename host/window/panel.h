// A panel of settings over the picture, drawn with Dear ImGui: collapsible, starting
// collapsed in the top-left corner. Its rows are plain values the caller describes anew
// each frame and reads back (what the user changed), so the caller needs no ImGui.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vkpt::internal {

struct PanelRow {
  enum class Kind { kText, kSlider, kCheckbox, kChoice, kButton };
  Kind kind = Kind::kText;
  std::string label;   // kText: the line itself
  double value = 0.0;  // kSlider: the number; kCheckbox: 0 or 1; kChoice: the index
  double lo = 0.0;     // kSlider's range
  double hi = 1.0;
  bool integer = false;  // kSlider: whole numbers
  bool logarithmic = false;
  std::vector<std::string> choices;  // kChoice
  bool changed = false;              // set by DrawPanel: the user changed it, or pressed the button

  static PanelRow Text(std::string line) { return Make(Kind::kText, std::move(line), 0.0); }
  static PanelRow Slider(std::string label, double value, double lo, double hi, bool integer = false,
                         bool logarithmic = false) {
    PanelRow r = Make(Kind::kSlider, std::move(label), value);
    r.lo = lo, r.hi = hi, r.integer = integer, r.logarithmic = logarithmic;
    return r;
  }
  static PanelRow Checkbox(std::string label, bool on) { return Make(Kind::kCheckbox, std::move(label), on); }
  static PanelRow Choice(std::string label, size_t index, std::vector<std::string> choices) {
    PanelRow r = Make(Kind::kChoice, std::move(label), double(index));
    r.choices = std::move(choices);
    return r;
  }
  static PanelRow Button(std::string label) { return Make(Kind::kButton, std::move(label), 0.0); }

 private:
  static PanelRow Make(Kind kind, std::string label, double value) {
    PanelRow r;
    r.kind = kind;
    r.label = std::move(label);
    r.value = value;
    return r;
  }
};

// Draws `rows` in a window titled `title`, between Presenter::BeginOverlay and Show; sets
// each row's `changed` and its new value.
void DrawPanel(const std::string& title, std::vector<PanelRow>& rows);

}  // namespace vkpt::internal
