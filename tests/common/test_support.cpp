// SPDX-License-Identifier: MIT
#include "tests/common/test_support.h"

#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

namespace lamina::test {

std::string DataPath(const std::string& relative) {
  return std::string(LAMINA_TEST_DATA_DIR) + "/" + relative;
}

std::string WorldsPath(const std::string& relative) {
  return std::string(LAMINA_WORLDS_DIR) + "/" + relative;
}

std::string ScratchDir() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "none";
  for (char& c : name) {
    if (c == '/') c = '_';
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "lamina-tests" / name;
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string WriteScratchFile(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::path(ScratchDir()) / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

}  // namespace lamina::test
