// SPDX-License-Identifier: MIT
// The editor driven like a user drives it: `lamina` runs in its own Xvfb server and xdotool sends
// real X input events (pointer motion, buttons, keys) to its window; the editor writes one JSON
// line per frame (--trace) and runs in lockstep (1/60 s of simulated time per frame, so the
// physics does not depend on how fast this machine draws). Skipped with a message when Xvfb or
// xdotool is missing (cmake/setup-deps.sh installs both).
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/math_types.h"
#include "core/render/camera.h"
#include "ui/viewer/tool_geometry.h"

namespace lamina::ui {
namespace {

using nlohmann::json;

const std::string kBin = LAMINA_BIN_DIR;
const std::string kBoxes = std::string(LAMINA_TEST_DATA_DIR) + "/editor/two_boxes.xml";
constexpr int kWidth = 800, kHeight = 600;
// looking at the boxes from -y, level with them: x to the right, z up on screen
const char* kCamera = "target=0.25,0,0.1;yaw=-90;pitch=0;dist=2";

bool Have(const char* program) {
  return std::system((std::string("command -v ") + program + " > /dev/null 2>&1").c_str()) == 0;
}

core::OrbitCamera TestCamera() {
  core::OrbitCamera camera;
  camera.target = core::Vec3(0.25, 0, 0.1);
  camera.yaw = -90.0;
  camera.pitch = 0.0;
  camera.distance = 2.0;
  return camera;
}

// pixel of world point p in the editor's view
std::pair<int, int> Pixel(const core::Vec3& p) {
  const auto pixel = ProjectToPixels(TestCamera(), kWidth, kHeight, p);
  return {static_cast<int>(std::lround(pixel->x())), static_cast<int>(std::lround(pixel->y()))};
}

std::vector<json> ReadTrace(const std::string& path) {
  std::vector<json> lines;
  std::ifstream file(path);
  for (std::string line; std::getline(file, line);) {
    if (!line.empty()) lines.push_back(json::parse(line));
  }
  return lines;
}

// the display number Xvfb wrote to `path` ("" if it did not start within 10 s)
std::string ReadDisplay(const std::string& path) {
  for (int i = 0; i < 200; ++i) {
    std::ifstream file(path);
    std::string number;
    if (file >> number) return number;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return "";
}

// An Xvfb server of its own and `lamina` in it, in the background.
class EditorRun {
 public:
  EditorRun(const std::string& name, int frames, const std::string& options) : name_(name) {
    std::remove(trace().c_str());
    std::remove((name + ".exit").c_str());
    std::remove((name + ".display").c_str());
    // Xvfb picks a free display and writes its number (-displayfd)
    std::system(("Xvfb -displayfd 1 -screen 0 1024x768x24 > " + name + ".display 2> " + name +
                 "_xvfb.log & echo $! > " + name + "_xvfb.pid")
                    .c_str());
    display_ = ":" + ReadDisplay(name + ".display");
    std::system(("(DISPLAY=" + display_ + " " + kBin + "/lamina " + kBoxes +
                 " --lockstep --no-ui --size 800x600 --camera '" + kCamera + "' --frames " +
                 std::to_string(frames) + " --trace " + trace() + " " + options + " > " + name +
                 ".log 2>&1; echo $? > " + name + ".exit) &")
                    .c_str());
  }
  ~EditorRun() { std::system(("kill $(cat " + name_ + "_xvfb.pid) 2> /dev/null").c_str()); }

  std::string trace() const { return name_ + ".jsonl"; }
  /// Waits until the editor has drawn `frames` frames.
  bool WaitForFrames(size_t frames) const {
    for (int i = 0; i < 600; ++i) {
      if (ReadTrace(trace()).size() >= frames) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }
  /// Runs xdotool with `arguments` against this server.
  void Do(const std::string& arguments) const {
    std::system(("DISPLAY=" + display_ + " xdotool " + arguments).c_str());
  }
  void Pause(int milliseconds) const {
    std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
  }
  /// Waits for the editor to end; its exit code.
  int Wait() const {
    for (int i = 0; i < 1200; ++i) {
      std::ifstream exit_file(name_ + ".exit");
      int code = -1;
      if (exit_file >> code) return code;
      Pause(50);
    }
    return -1;
  }

 private:
  std::string name_, display_;
};

core::Vec3 Vec(const json& value) {
  return core::Vec3(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
}

// Ctrl + right drag on the left box, up and to the left: the mouse spring pulls the grabbed point
// toward the cursor. Checked from the trace: while the box is in the air (gravity and the spring
// are its only forces) its momentum changes by the integral of the reported spring force plus its
// weight (within 10 % of the spring's impulse), and the force points toward the cursor's target.
TEST(EditorScriptTest, AForceDragAcceleratesTheBoxTowardTheCursorAsTheSpringLawSays) {
  if (!Have("Xvfb") || !Have("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool";
  EditorRun run("force_drag", 400, "");
  ASSERT_TRUE(run.WaitForFrames(60));  // the window is mapped and takes input
  run.Pause(300);
  const auto [x, y] = Pixel(core::Vec3(0.0, -0.1, 0.1));  // the left box's front face centre
  std::cout << "grabbing at pixel " << x << ", " << y << "\n";
  run.Do("mousemove " + std::to_string(x) + " " + std::to_string(y));
  run.Pause(200);
  run.Do("keydown ctrl mousedown 3");
  for (int step = 1; step <= 10; ++step) {
    run.Do("mousemove " + std::to_string(x - 4 * step) + " " + std::to_string(y - 12 * step));
    run.Pause(40);
  }
  run.Pause(800);
  run.Do("mouseup 3 keyup ctrl");
  ASSERT_EQ(run.Wait(), 0);
  const std::vector<json> trace = ReadTrace(run.trace());
  const double m = 1.0, dt = 1.0 / 60.0;
  const core::Vec3 g(0, 0, -9.8);
  core::Vec3 impulse = core::Vec3::Zero(), momentum_change = core::Vec3::Zero();
  core::Vec3 spring = core::Vec3::Zero();  // the spring's part of the impulse
  int airborne = 0, toward = 0, pulling = 0;
  for (size_t i = 1; i < trace.size(); ++i) {
    const json& a = trace[i - 1];
    const json& b = trace[i];
    if (!a["dragging"].get<bool>() || !b["dragging"].get<bool>()) continue;
    const core::Vec3 force = Vec(b["drag"]["force"]);
    const core::Vec3 stretch = Vec(b["drag"]["target"]) - Vec(b["drag"]["point"]);
    if (stretch.norm() > 0.02) {
      ++pulling;
      toward += force.dot(stretch) > 0.0;
    }
    const bool in_air = Vec(a["objects"][0]).z() > 0.13 && Vec(b["objects"][0]).z() > 0.13;
    if (!in_air) continue;
    ++airborne;
    spring += Vec(b["drag"]["impulse"]);
    impulse += Vec(b["drag"]["impulse"]) + m * g * dt;
    momentum_change += m * (Vec(b["sampled_velocity"][1]) - Vec(a["sampled_velocity"][1]));
  }
  std::cout << "frames pulling " << pulling << " (toward the cursor " << toward << "), airborne "
            << airborne << ": momentum change " << momentum_change.transpose()
            << " N·s, impulse of the spring and the weight " << impulse.transpose() << " N·s\n";
  ASSERT_GT(airborne, 10) << "the box was not lifted";
  EXPECT_GT(toward, 0.9 * pulling);
  EXPECT_LT((momentum_change - impulse).norm(), 0.1 * spring.norm());
  EXPECT_GT(spring.z(), 0.0);
}

}  // namespace
}  // namespace lamina::ui
