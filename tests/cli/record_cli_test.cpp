// SPDX-License-Identifier: MIT
// `lamina-headless record`: frames in simulation time as PNG files (or an .mp4 through ffmpeg
// when it is installed), and bad options.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::CommandResult;
using test::RunHeadless;

// width and height from a PNG's IHDR chunk (big-endian at bytes 16..23)
std::pair<int, int> PngSize(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  unsigned char header[24] = {};
  file.read(reinterpret_cast<char*>(header), sizeof(header));
  const auto read = [&header](int at) {
    return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3];
  };
  return {read(16), read(20)};
}

std::string BounceWorld() {
  return test::WorldsPath("klampt/simulation_test_worlds/bounce_test.xml");
}

// 0.1 s at 20 fps: frames at t = 0, 0.05 and 0.1 s
TEST(RecordCommandTest, WritesOnePngPerFrameInSimulationTime) {
  const std::string dir = test::ScratchDir() + "/frames";
  const CommandResult result =
      RunHeadless("record " + BounceWorld() + " --duration 0.1 --fps 20 --size 160x120 -o " + dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* name : {"frame_00000.png", "frame_00001.png", "frame_00002.png"}) {
    const std::string path = dir + "/" + name;
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    EXPECT_EQ(PngSize(path), std::make_pair(160, 120)) << path;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/frame_00003.png"));
  EXPECT_NE(result.err.find("100%"), std::string::npos) << "no progress bar: " << result.err;
}

// an .mp4 goes through ffmpeg when it is on the PATH, and falls back to PNG frames otherwise
TEST(RecordCommandTest, Mp4UsesFfmpegOrFallsBackToFrames) {
  const std::string mp4 = test::ScratchDir() + "/clip.mp4";
  const CommandResult result =
      RunHeadless("record " + BounceWorld() + " --duration 0.1 --fps 20 --size 160x120 -o " + mp4);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const bool have_ffmpeg = std::system("command -v ffmpeg > /dev/null 2>&1") == 0;
  if (have_ffmpeg) {
    ASSERT_TRUE(std::filesystem::exists(mp4));
    EXPECT_GT(std::filesystem::file_size(mp4), 0u);
  } else {
    EXPECT_TRUE(std::filesystem::exists(test::ScratchDir() + "/clip_frames/frame_00002.png"))
        << result.err;
  }
}

TEST(RecordCommandTest, BadFpsIsAUsageError) {
  const CommandResult result =
      RunHeadless("record " + BounceWorld() + " --duration 0.1 --fps 0 -o " + test::ScratchDir());
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.err.find("fps"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace lamina
