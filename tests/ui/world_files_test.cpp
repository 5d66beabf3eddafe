// SPDX-License-Identifier: MIT
// The Open-world list: XML files whose root element is <world>, not motions or other XML.
#include "ui/viewer/world_files.h"

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "tests/common/test_support.h"

namespace lamina::ui {
namespace {

TEST(WorldFilesTest, RootElementDecides) {
  EXPECT_TRUE(IsWorldFile(test::WriteScratchFile(
      "world_files/a.xml",
      "<?xml version=\"1.0\"?>\n<!-- a <comment> -->\n  <world>\n</world>\n")));
  EXPECT_TRUE(IsWorldFile(test::WriteScratchFile("world_files/b.xml", "<world name=\"x\"/>")));
  EXPECT_TRUE(IsWorldFile(
      test::WriteScratchFile("world_files/f.xml", "<!DOCTYPE world>\n<world></world>")));
  EXPECT_FALSE(IsWorldFile(test::WriteScratchFile(
      "world_files/c.xml", "<?xml version=\"1.0\"?>\n<multipath>\n</multipath>\n")));
  EXPECT_FALSE(IsWorldFile(test::WriteScratchFile("world_files/d.xml", "<worldly/>")));
  EXPECT_FALSE(IsWorldFile(test::WriteScratchFile("world_files/e.xml", "")));
  EXPECT_FALSE(IsWorldFile(test::ScratchDir() + "/world_files/missing.xml"));
}

TEST(WorldFilesTest, TheExampleWorldsWithoutTheMotions) {
  const std::vector<std::string> files = WorldFilesUnder(test::WorldsPath("klampt"));
  const auto listed = [&](const std::string& relative) {
    return std::find(files.begin(), files.end(), test::WorldsPath(relative)) != files.end();
  };
  EXPECT_TRUE(listed("klampt/athlete_fractal_1.xml"));
  EXPECT_TRUE(listed("klampt/simulation_test_worlds/stacktest.xml"));
  EXPECT_FALSE(listed("klampt/motions/athlete_flex.xml"));  // a MultiPath
  EXPECT_TRUE(std::is_sorted(files.begin(), files.end()));
}

}  // namespace
}  // namespace lamina::ui
