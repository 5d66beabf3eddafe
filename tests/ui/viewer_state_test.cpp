// SPDX-License-Identifier: MIT
// --panels: a list of panel names shows exactly those panels; "all" and "none"; an unknown name
// is refused with the list of known ones.
#include "ui/viewer/viewer_state.h"

#include <string>

#include <gtest/gtest.h>

namespace lamina::ui {
namespace {

int ShownCount(const PanelVisibility& panels) {
  int count = 0;
  for (const PanelEntry& panel : kPanels) count += panels.*panel.shown ? 1 : 0;
  return count;
}

TEST(PanelListTest, NamesShowExactlyTheirPanels) {
  PanelVisibility panels;
  std::string error;
  ASSERT_TRUE(ParsePanelList("plots,settings", &panels, &error)) << error;
  EXPECT_TRUE(panels.plots);
  EXPECT_TRUE(panels.settings);
  EXPECT_EQ(ShownCount(panels), 2);
  for (const PanelEntry& panel : kPanels) {
    PanelVisibility one;
    ASSERT_TRUE(ParsePanelList(panel.name, &one, &error)) << error;
    EXPECT_TRUE(one.*panel.shown) << panel.name;
    EXPECT_EQ(ShownCount(one), 1) << panel.name << " shares its flag";
  }
}

TEST(PanelListTest, AllNoneAndUnknownNames) {
  PanelVisibility panels;
  std::string error;
  ASSERT_TRUE(ParsePanelList("all", &panels, &error));
  EXPECT_EQ(ShownCount(panels), static_cast<int>(std::size(kPanels)));
  ASSERT_TRUE(ParsePanelList("none", &panels, &error));
  EXPECT_EQ(ShownCount(panels), 0);
  const PanelVisibility before = panels;
  EXPECT_FALSE(ParsePanelList("plots,plot", &panels, &error));
  EXPECT_NE(error.find("'plot'"), std::string::npos) << error;
  EXPECT_NE(error.find("inspector"), std::string::npos) << error;
  EXPECT_EQ(panels.plots, before.plots);  // a refused list changes nothing
}

}  // namespace
}  // namespace lamina::ui
