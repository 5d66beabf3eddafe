// SPDX-License-Identifier: MIT
// The editor driven like a user drives it: `lamina` runs in its own Xvfb server and xdotool sends
// real X input events (pointer motion, buttons, keys) to its window; the editor writes one JSON
// line per frame (--trace) and runs in lockstep (1/60 s of simulated time per frame, so the
// physics does not depend on how fast this machine draws). Skipped with a message when Xvfb or
// xdotool is missing (cmake/setup-deps.sh installs both).
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
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
    json parsed = json::parse(line, nullptr, false);  // (a line being written is skipped)
    if (!parsed.is_discarded()) lines.push_back(std::move(parsed));
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
  EditorRun(const std::string& name, int frames, const std::string& options,
            const std::string& world = kBoxes)
      : name_(name) {
    std::remove(trace().c_str());
    std::remove((name + ".exit").c_str());
    std::remove((name + ".display").c_str());
    // Xvfb picks a free display and writes its number (-displayfd)
    std::system(("Xvfb -displayfd 1 -screen 0 1024x768x24 > " + name + ".display 2> " + name +
                 "_xvfb.log & echo $! > " + name + "_xvfb.pid")
                    .c_str());
    display_ = ":" + ReadDisplay(name + ".display");
    // the boxes' camera unless the options choose one
    const std::string camera = options.find("--camera") == std::string::npos
                                   ? " --camera '" + std::string(kCamera) + "'"
                                   : "";
    std::system(("(DISPLAY=" + display_ + " " + kBin + "/lamina " + world +
                 " --lockstep --size 800x600" + camera + " --frames " + std::to_string(frames) +
                 " --trace " + trace() + " " + options + " > " + name + ".log 2>&1; echo $? > " +
                 name + ".exit) &")
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
  /// The last frame traced (null before the first).
  json Last() const {
    std::vector<json> lines = ReadTrace(trace());
    return lines.empty() ? json() : lines.back();
  }
  /// Waits up to 30 s for a traced frame that satisfies `done`; that frame (null on time-out).
  json WaitFor(const std::function<bool(const json&)>& done) const {
    for (int i = 0; i < 600; ++i) {
      const json line = Last();
      if (!line.is_null() && done(line)) return line;
      Pause(50);
    }
    return json();
  }
  /// Waits for the named item (item_registry.h) to be drawn; its frame (null on time-out).
  json WaitForItem(const std::string& name) const {
    return WaitFor([&](const json& line) { return line["items"].contains(name); });
  }
  /// A left click on item `name` of `line`, `from_left` pixels from its left edge (< 0: its
  /// centre), with `modifier` ("ctrl", "") held.
  void ClickItem(const json& line, const std::string& name, int from_left = -1,
                 const std::string& modifier = "") const {
    const json& rect = line["items"][name]["rect"];
    const double x0 = rect[0], y0 = rect[1], x1 = rect[2], y1 = rect[3];
    const int x = static_cast<int>(from_left < 0 ? (x0 + x1) / 2 : x0 + from_left);
    const int y = static_cast<int>((y0 + y1) / 2);
    Do("mousemove " + std::to_string(x) + " " + std::to_string(y));
    Pause(150);
    if (!modifier.empty()) Do("keydown " + modifier);
    Pause(150);
    Do("click 1");
    Pause(150);
    if (!modifier.empty()) Do("keyup " + modifier);
    Pause(150);
  }
  /// Presses keys as a user does ("ctrl+z", "Return"): down, held for some frames, up. (ImGui
  /// 1.86 reads key states once a frame: a press and release within one frame is not seen.)
  void Press(const std::string& keys) const {
    Do("keydown " + keys);
    Pause(150);
    Do("keyup " + keys);
    Pause(150);
  }
  void Type(const std::string& text) const {
    Do("type --delay 60 '" + text + "'");
    Pause(150);
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
  EditorRun run("force_drag", 400, "--no-ui");
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

const char* kFriction = "objects[0].kFriction";

// the left box's contact with the ground in a traced frame (null if it has none)
json GroundContact(const json& line) {
  for (const json& contact : line["contacts"]) {
    if (contact["partner"] == 0) return contact;
  }
  return json();
}

std::string ItemText(const json& line, const std::string& name) {
  return line["items"].contains(name) ? line["items"][name]["text"].get<std::string>() : "";
}

double HarmonicMean(double a, double b) {
  return 2.0 * a * b / (a + b);
}

// The inspector, as a user works it: a click in the World tree selects the left box, a
// Ctrl+click on its kFriction field and typing 0.2 changes it, and the blended friction of its
// contact with the ground — the value the contact rows use — becomes the harmonic mean of 0.2
// and the ground's. Ctrl+Z brings 0.5 back (field and blend), Ctrl+Shift+Z 0.2 again; typing
// 0.2 over 0.2 changes nothing; Save As (typing a path into its dialog) writes it, and the saved
// world opened again shows 0.2. No frame ever sees a friction other than 0.5 or 0.2.
TEST(EditorScriptTest, AnInspectorFrictionEditChangesTheBlendUndoRedoAndSaveAsKeepIt) {
  if (!Have("Xvfb") || !Have("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool";
  const std::string saved = std::filesystem::absolute("friction_edit_saved.xml").string();
  std::filesystem::remove(saved);
  {
    EditorRun run("friction_edit", 3000, "");
    ASSERT_TRUE(run.WaitForFrames(60));
    run.Pause(300);
    json line = run.WaitForItem("tree.1");
    ASSERT_FALSE(line.is_null()) << "the World tree shows no entry for the left box";
    EXPECT_EQ(ItemText(line, "tree.1"), "left");
    run.ClickItem(line, "tree.1");
    line = run.WaitFor([](const json& l) {
      return l["items"].contains(kFriction) && !GroundContact(l).is_null();
    });
    ASSERT_FALSE(line.is_null()) << "selecting the box did not show its kFriction field";
    EXPECT_EQ(line["selected"], 1);
    EXPECT_EQ(ItemText(line, kFriction), "0.5");
    const double ground = GroundContact(line)["partner_friction"];
    EXPECT_NEAR(GroundContact(line)["friction"].get<double>(), HarmonicMean(0.5, ground), 1e-12);

    run.ClickItem(line, kFriction, 20, "ctrl");  // Ctrl+click: type a value
    run.Type("0.2");
    run.Press("Return");
    const auto blend_is = [](double value) {
      return [value](const json& l) {
        const json contact = GroundContact(l);
        return !contact.is_null() &&
               std::abs(contact["own_friction"].get<double>() - value) < 1e-12;
      };
    };
    line = run.WaitFor(blend_is(0.2));
    ASSERT_FALSE(line.is_null()) << "the typed friction did not reach the simulation";
    EXPECT_EQ(ItemText(line, kFriction), "0.2");
    EXPECT_NEAR(GroundContact(line)["friction"].get<double>(), HarmonicMean(0.2, ground), 1e-12);
    EXPECT_TRUE(line["dirty"].get<bool>());
    EXPECT_EQ(line["undo"], "kFriction of left");

    run.Press("ctrl+z");
    line = run.WaitFor(blend_is(0.5));
    ASSERT_FALSE(line.is_null()) << "Ctrl+Z did not bring the friction back";
    EXPECT_EQ(ItemText(line, kFriction), "0.5");
    EXPECT_NEAR(GroundContact(line)["friction"].get<double>(), HarmonicMean(0.5, ground), 1e-12);
    EXPECT_FALSE(line["dirty"].get<bool>());

    run.Press("ctrl+shift+z");
    line = run.WaitFor(blend_is(0.2));
    ASSERT_FALSE(line.is_null()) << "Ctrl+Shift+Z did not redo the edit";
    EXPECT_EQ(ItemText(line, kFriction), "0.2");

    // typing the value the field already has changes nothing: "0" and "0." on the way are held
    // back (the check over every frame below) and the end equals the start
    const int frame_before = line["frame"];
    run.ClickItem(line, kFriction, 20, "ctrl");
    run.Type("0.2");
    run.Press("Return");
    line = run.WaitFor([&](const json& l) { return l["frame"].get<int>() > frame_before + 20; });
    ASSERT_FALSE(line.is_null());
    EXPECT_EQ(ItemText(line, kFriction), "0.2");

    run.Press("ctrl+shift+s");
    line = run.WaitForItem("dialog.save_as.path");
    ASSERT_FALSE(line.is_null()) << "Ctrl+Shift+S did not open Save As";
    run.Press("ctrl+a");
    run.Type(saved);
    line = run.WaitFor([&](const json& l) { return ItemText(l, "dialog.save_as.path") == saved; });
    ASSERT_FALSE(line.is_null()) << "the typed path did not reach the dialog";
    run.Press("Return");
    line = run.WaitFor([&](const json& l) { return l["path"] == saved && !l["dirty"]; });
    ASSERT_FALSE(line.is_null()) << "Save As did not write " << saved;
    run.Press("ctrl+q");  // nothing unsaved: quits without asking
    EXPECT_EQ(run.Wait(), 0);
  }
  // the keystrokes on the way ("0", "0.") were never applied: the simulation saw 0.5 and 0.2 only
  for (const json& frame : ReadTrace("friction_edit.jsonl")) {
    const json contact = GroundContact(frame);
    if (contact.is_null()) continue;
    const double own = contact["own_friction"];
    EXPECT_TRUE(own == 0.5 || own == 0.2) << "frame " << frame["frame"] << ": friction " << own;
  }
  std::ifstream file(saved);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("kFriction=\"0.2\""), std::string::npos) << text;

  EditorRun reopened("friction_reopen", 90, "--select 1 --paused", saved);
  EXPECT_EQ(reopened.Wait(), 0);
  const json last = reopened.Last();
  EXPECT_EQ(ItemText(last, kFriction), "0.2");
}

// Ctrl + middle drag moves the left box as a kinematic target, level along +x, through the
// place where the right box stands: the right box is pushed along +x (it started at rest at
// x = 0.5 m) while the dragged box follows the cursor.
TEST(EditorScriptTest, AKinematicDragPushesTheSecondBox) {
  if (!Have("Xvfb") || !Have("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool";
  EditorRun run("kinematic_drag", 300, "--no-ui");
  ASSERT_TRUE(run.WaitForFrames(60));
  run.Pause(300);
  const auto [x, y] = Pixel(core::Vec3(0.0, -0.1, 0.1));  // the left box's front face centre
  const auto [x_end, y_end] = Pixel(core::Vec3(0.5, -0.1, 0.1));  // 0.5 m to the right
  run.Do("mousemove " + std::to_string(x) + " " + std::to_string(y));
  run.Pause(200);
  run.Do("keydown ctrl mousedown 2");
  constexpr int kMoves = 25;
  for (int step = 1; step <= kMoves; ++step) {
    run.Do("mousemove " + std::to_string(x + (x_end - x) * step / kMoves) + " " +
           std::to_string(y + (y_end - y) * step / kMoves));
    run.Pause(60);
  }
  run.Pause(500);
  run.Do("mouseup 2 keyup ctrl");
  ASSERT_EQ(run.Wait(), 0);
  const std::vector<json> trace = ReadTrace(run.trace());
  ASSERT_GT(trace.size(), 100u);
  double right_before = 0.0, right_after = 0.0, left_furthest = 0.0;
  int kinematic_frames = 0;
  bool started = false;
  for (const json& line : trace) {
    if (!line.contains("objects")) continue;
    const double left = Vec(line["objects"][0]).x(), right = Vec(line["objects"][1]).x();
    if (line["kinematic"].size() > 0) {
      ++kinematic_frames;
      if (!started) right_before = right;
      started = true;
    }
    left_furthest = std::max(left_furthest, left);
    right_after = right;
  }
  std::cout << "kinematic frames " << kinematic_frames
            << ": the right box moved from x = " << right_before << " to " << right_after
            << " m; the dragged box reached x = " << left_furthest << " m\n";
  ASSERT_GT(kinematic_frames, 20) << "the drag never took the box";
  EXPECT_NEAR(right_before, 0.5, 0.005);
  EXPECT_GT(left_furthest, 0.35);  // past where the boxes touch (0.3 m)
  // pushed by at least how far the dragged box went past touching it (less the padding)
  EXPECT_GT(right_after - right_before, left_furthest - 0.3 - 0.03);
}

// The Robot panel of Klamp't's planar 3R arm: a click opens driver 0's rows, the mouse wheel
// scrolls to its servoP, Ctrl+click and typing sets it to 120; Reset (its button) starts the
// simulation again and the gain stays 120 — gains are part of the world, not of the run. Quitting
// with the edit unsaved asks first, and Discard quits.
TEST(EditorScriptTest, AGainEditedInTheRobotPanelSurvivesReset) {
  if (!Have("Xvfb") || !Have("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool";
  const std::string arm = std::string(LAMINA_TEST_DATA_DIR) + "/editor/planar_arm.xml";
  const std::string gain = "robots[0].drivers[0].servoP";
  EditorRun run("robot_gain", 5000, "--select 2", arm);  // link 0 selected
  ASSERT_TRUE(run.WaitForFrames(60));
  run.Pause(300);
  json line = run.WaitForItem("robots[0].drivers[0]");
  ASSERT_FALSE(line.is_null()) << "the Robot panel shows no driver 0";
  run.ClickItem(line, "robots[0].drivers[0]", 10);  // on its arrow
  for (int scroll = 0; scroll < 12 && !run.Last()["items"].contains(gain); ++scroll) {
    run.Do("click 5");  // the wheel, over the driver's node (the Robot panel)
    run.Pause(150);
  }
  line = run.WaitForItem(gain);
  ASSERT_FALSE(line.is_null()) << "scrolling did not bring driver 0's servoP into view";
  EXPECT_EQ(ItemText(line, gain), "50");
  run.ClickItem(line, gain, 20, "ctrl");
  run.Type("120");
  run.Press("Return");
  line = run.WaitFor([&](const json& l) { return ItemText(l, gain) == "120"; });
  ASSERT_FALSE(line.is_null()) << "the typed gain was not taken";
  EXPECT_TRUE(line["dirty"].get<bool>());
  EXPECT_EQ(line["undo"], "servoP of planar3R driver 'Link 0'");
  const double edited_at = line["time"];

  line = run.WaitForItem("button.reset");
  ASSERT_FALSE(line.is_null()) << "no Reset button";
  run.ClickItem(line, "button.reset");
  line = run.WaitFor([&](const json& l) { return l["time"].get<double>() < edited_at; });
  ASSERT_FALSE(line.is_null()) << "Reset did not start the simulation again";
  EXPECT_EQ(ItemText(line, gain), "120");
  EXPECT_TRUE(line["dirty"].get<bool>());

  run.Press("ctrl+q");
  line = run.WaitForItem("dialog.confirm.discard");
  ASSERT_FALSE(line.is_null()) << "quitting with an unsaved edit did not ask";
  run.ClickItem(line, "dialog.confirm.discard");
  EXPECT_EQ(run.Wait(), 0);
  EXPECT_LT(ReadTrace(run.trace()).size(), 4000u) << "Discard did not quit";
}

// The pose tool on a robot (paused, G, a left drag): Klamp't's ATHLETE moves by its floating
// base. A drag of 100 pixels to the right (the camera looks along +y, so right is +x) changes the
// initial configuration's base x by about 0.55 m (4.4 m across 800 pixels at 4 m) and nothing
// else: the legs keep their values. One undo step, "move ATHLETE", and the world is unsaved.
TEST(EditorScriptTest, ThePoseToolMovesARobotByItsFloatingBase) {
  if (!Have("Xvfb") || !Have("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool";
  const std::string athlete = std::string(LAMINA_WORLDS_DIR) + "/klampt/athlete_fractal_1.xml";
  EditorRun run("robot_pose", 5000,
                "--no-ui --paused --camera 'target=0,0,0.5;yaw=-90;pitch=15;dist=4'", athlete);
  ASSERT_TRUE(run.WaitForFrames(30));
  run.Pause(300);
  const json before = run.Last();
  run.Press("g");
  run.Do("mousemove 380 275");  // the hexagon's front face
  run.Pause(150);
  run.Do("mousedown 1");
  for (int step = 1; step <= 10; ++step) {
    run.Do("mousemove " + std::to_string(380 + 10 * step) + " 275");
    run.Pause(50);
  }
  run.Pause(300);
  run.Do("mouseup 1");
  const json after = run.WaitFor([](const json& l) { return l["undo"] == "move ATHLETE"; });
  ASSERT_FALSE(after.is_null()) << "the pose tool did not move the robot: "
                                << run.Last()["message"];
  run.Pause(300);
  const json line = run.Last();
  run.Press("ctrl+q");
  const json dialog = run.WaitForItem("dialog.confirm.discard");
  if (!dialog.is_null()) run.ClickItem(dialog, "dialog.confirm.discard");
  const std::vector<double> q0 = before["robots"][0], q1 = line["robots"][0];
  ASSERT_EQ(q0.size(), q1.size());
  std::cout << "base x " << q0[0] << " -> " << q1[0] << ", y " << q0[1] << " -> " << q1[1] << ", z "
            << q0[2] << " -> " << q1[2] << "\n";
  EXPECT_NEAR(q1[0] - q0[0], 0.55, 0.15);
  EXPECT_NEAR(q1[1], q0[1], 0.1);
  for (size_t i = 3; i < 6; ++i) EXPECT_NEAR(q1[i], q0[i], 1e-9) << "base angle " << i;
  // (the frames show the simulation's state: joint values read back from ODE bodies, to 1e-15)
  for (size_t i = 6; i < q0.size(); ++i) EXPECT_NEAR(q1[i], q0[i], 1e-9) << "link " << i;
  EXPECT_TRUE(line["dirty"].get<bool>());
}

}  // namespace
}  // namespace lamina::ui
