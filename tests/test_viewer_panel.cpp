// The viewer's overlay without a window (viewer/viewer_panel.h): its rows show the
// render's figures and the settings with the schema's ranges; a change to a row becomes
// the display's, the render's or the scene's, as it should; a time plays and wraps.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "viewer/viewer_panel.h"
#include "vkpt/settings_schema.h"

namespace vkpt::internal {
namespace {

PanelSettings Animated() {
  PanelSettings s;
  s.environmentRotation = 0.0;
  s.environmentIntensity = 1.0;
  s.variants = {"red", "green"};
  s.animations = {{0, "walk", 2.0}, {1, "", 4.0}};
  s.animation = "walk";
  return s;
}

// The row labelled `label`.
PanelRow& Row(std::vector<PanelRow>& rows, const std::string& label) {
  for (PanelRow& r : rows)
    if (r.label == label) return r;
  ADD_FAILURE() << "no row " << label;
  return rows.front();
}

TEST(ViewerPanel, RowsShowTheFiguresAndTheSchemasRanges) {
  PanelStats stats;
  stats.spp = 12, stats.maxSpp = 64, stats.samplesPerSecond = 2.5e6, stats.seconds = 3.0, stats.relMse = 0.004;
  stats.engine = "cpu (2 threads)";
  std::vector<PanelRow> rows = PanelRows(Animated(), stats);
  EXPECT_EQ(rows[0].label, "12 of 64 spp, 2.5 Msamples/s");
  EXPECT_EQ(rows[1].label, "3.0 s, estimated relMSE 0.004");
  EXPECT_EQ(Row(rows, "max depth").lo, SettingOf("max_depth").range->lo);
  EXPECT_TRUE(Row(rows, "max depth").integer);
  EXPECT_EQ(Row(rows, "variant").choices, (std::vector<std::string>{"(none)", "red", "green"}));
  EXPECT_EQ(Row(rows, "animation").choices, (std::vector<std::string>{"(none)", "walk", "1"}));
  EXPECT_EQ(Row(rows, "animation").value, 1.0);
  EXPECT_EQ(Row(rows, "time").hi, 2.0);
  // Without a map, variants or animations, their rows are empty lines (not drawn).
  rows = PanelRows(PanelSettings{}, stats);
  for (const char* absent : {"environment rotation", "variant", "animation", "time", "play"})
    for (const PanelRow& r : rows) EXPECT_NE(r.label, absent);
}

TEST(ViewerPanel, EachChangeGoesWhereItBelongs) {
  PanelSettings s = Animated();
  std::vector<PanelRow> rows = PanelRows(s, {});
  EXPECT_FALSE(ApplyPanel(rows, s).display);  // nothing changed
  Row(rows, "exposure").value = 1.5, Row(rows, "exposure").changed = true;
  Row(rows, "view").value = 1, Row(rows, "view").changed = true;
  PanelChange c = ApplyPanel(rows, s);
  EXPECT_TRUE(c.display && !c.render && c.scene.empty());
  EXPECT_EQ(s.display.exposure, 1.5f);
  EXPECT_EQ(s.display.view, View::kAgx);

  rows = PanelRows(s, {});
  Row(rows, "max depth").value = 4, Row(rows, "max depth").changed = true;
  Row(rows, "show").value = 3, Row(rows, "show").changed = true;
  c = ApplyPanel(rows, s);
  EXPECT_TRUE(c.render && !c.display && c.scene.empty());
  EXPECT_EQ(s.maxDepth, 4u);
  EXPECT_EQ(s.aov, "depth");
  EXPECT_EQ(RenderOptionsOf({}, s).aovs, std::vector<std::string>{"depth"});
  EXPECT_EQ(RenderOptionsOf({}, s).maxDepth, 4u);

  rows = PanelRows(s, {});
  Row(rows, "variant").value = 2, Row(rows, "variant").changed = true;
  Row(rows, "environment rotation").value = 90, Row(rows, "environment rotation").changed = true;
  Row(rows, "time").value = 0.5, Row(rows, "time").changed = true;
  c = ApplyPanel(rows, s);
  EXPECT_EQ(c.scene,
            (vkpt::ParameterMap{{"variant", std::string("green")}, {"environment/rotation", 90.0}, {"time", 0.5}}));

  rows = PanelRows(s, {});
  Row(rows, "animation").value = 0, Row(rows, "animation").changed = true;
  c = ApplyPanel(rows, s);
  EXPECT_EQ(c.scene, (vkpt::ParameterMap{{"animation", std::string()}, {"time", 0.0}}));
}

TEST(ViewerPanel, PlayingMovesTheTimeOnAndWraps) {
  PanelSettings s = Animated();
  std::vector<PanelRow> rows = PanelRows(s, {});
  Row(rows, "play").changed = true;
  ApplyPanel(rows, s);
  EXPECT_TRUE(s.playing);
  EXPECT_EQ(Row(rows = PanelRows(s, {}), "pause").kind, PanelRow::Kind::kButton);
  s.time = 1.5;
  EXPECT_DOUBLE_EQ(AdvanceTime(s, 0.25), 1.75);
  EXPECT_DOUBLE_EQ(AdvanceTime(s, 0.75), 0.0);  // past its 2 s: from the start
  // The render's own time and rotation give way to the scene's parameters.
  vkpt::RenderOptions given;
  given.time = 1.0;
  given.environmentRotation = 30.0f;
  EXPECT_FALSE(RenderOptionsOf(given, s).time.has_value());
  EXPECT_FALSE(RenderOptionsOf(given, s).environmentRotation.has_value());
}

}  // namespace
}  // namespace vkpt::internal
