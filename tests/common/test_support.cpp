// SPDX-License-Identifier: MIT
#include "tests/common/test_support.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "core/model/world_compare.h"

namespace lamina::test {

core::Pose PoseAt(const core::Vec3& position, const core::Mat3& rotation) {
  core::Pose pose = core::Pose::Identity();
  pose.linear() = rotation;
  pose.translation() = position;
  return pose;
}

core::VecX Vec(std::initializer_list<double> values) {
  core::VecX v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values) v[i++] = x;
  return v;
}

double SignedVolume(const core::TriangleMesh& mesh) {
  double volume = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
  }
  return volume;
}

std::string DataPath(const std::string& relative) {
  return LAMINA_TEST_DATA_DIR "/" + relative;
}

std::string WorldsPath(const std::string& relative) {
  return LAMINA_WORLDS_DIR "/" + relative;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
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

bool IsClosedAndConsistent(const core::TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    const auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end() || reverse->second != 1) return false;
  }
  return !directed.empty();
}

std::vector<std::string> LinkNames(const core::RobotDesc& robot) {
  std::vector<std::string> names;
  for (const core::LinkDesc& link : robot.links) names.push_back(link.name);
  return names;
}

std::vector<int> Parents(const core::RobotDesc& robot) {
  std::vector<int> parents;
  for (const core::LinkDesc& link : robot.links) parents.push_back(link.parent);
  return parents;
}

CommandResult RunHeadless(const std::string& arguments) {
  const std::string err_path = ScratchDir() + "/stderr.txt";
  const std::string command = LAMINA_BIN_DIR "/lamina-headless " + arguments + " 2>" + err_path;
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  size_t read = 0;
  while ((read = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.out.append(buffer.data(), read);
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_path);
  result.err.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
  return result;
}

namespace {

std::vector<core::ElementUid> Uids(const core::WorldDesc& world) {
  std::vector<core::ElementUid> uids;
  for (const auto& terrain : world.terrains) uids.push_back(terrain.uid);
  for (const auto& object : world.objects) uids.push_back(object.uid);
  for (const auto& robot : world.robots) uids.push_back(robot.uid);
  return uids;
}

}  // namespace

void ExpectSameWorld(const core::WorldDesc& a, const core::WorldDesc& b) {
  const std::vector<std::string> differences = core::CompareWorlds(a, b, 0.0);
  EXPECT_TRUE(differences.empty()) << differences.front();
  EXPECT_EQ(Uids(a), Uids(b));
}

}  // namespace lamina::test
