// SPDX-License-Identifier: MIT
// Mesh–mesh resting jitter (numerics §6 scene 12): a 0.2 m, 1 kg mesh cube (Klamp't's cube.off,
// 12 triangles) turned 0.3 rad about z rests on its 2.5 mm padding on the two-triangle mesh floor
// plane.off, across the floor's diagonal (worlds/accuracy/mesh_jitter.xml); friction 0.5,
// restitution 0.5; 1.5 s. Answer: it stays at rest (v = 0) on a steady set of contacts. After
// 0.5 s of settling the probe measures the RMS speed of the centre of mass (the error, m/s), the
// RMS angular speed, how far the cube moved, and the range of the contact-joint count from step
// to step (the world has one contact pair).
//
// Bars (numerics §6 scene 12): RMS resting speed < 1e-3 m/s and the contact count steady to
// within 1 over the last second, at 1 ms and 10 ms. Numerics also sweeps the padding and
// maxContacts: the variants mesh_jitter_pad0, _pad1 and _pad5 hold the same cube with padding 0,
// 1 and 5 mm, and the two with a boundary layer meet the same bars. Without one (pad0) the meshes
// touch with nothing between them: the exact solver holds the cube (1e-19 m moved) but rolls back
// nearly every step (1490 of 1500 at 1 ms), QuickStep reports contact unreliable throughout and
// jitters at 2e-4 m/s; its bar is only that the cube stays put (moves < 1 mm), and the report shows
// the rollbacks. maxContacts does not matter here (the cube has 4 contacts: 4, 20 and 100 give
// the same run, measured), so it has no variant; the maxContacts sweep is on the soft ball of
// scene_soft_ball.cpp, whose patch has hundreds of contacts.
//
// The scanned tray (worlds/accuracy/scanned_tray.xml, numerics' "scanned or non-watertight
// object on a table"): an open 0.3 m tray with no lid whose bottom grid has its inner vertices
// moved by up to 0.3 mm, resting on its 2.5 mm padding on the mesh floor; same probe and bars.
// With hard contacts the layer's overlap is pushed out, so the tray settles onto its three or
// four lowest bumps, as a real bumpy object does: 3 contacts at 1 ms, at rest to 1e-16 m/s
// under dWorldStep and 1e-13 m/s under the Newton solver; QuickStep(20) rocks on its bumps at
// 1 ms (5.6e-4 m/s RMS, the contact count varying by 4) but not at 10 ms.
//
// Gripper pad (numerics §6 scene 12, "gripper pad pressing a mesh";
// worlds/accuracy/gripper_pad.xml): the same mesh cube on the same floor, pressed from above by a
// robot's 6 × 6 cm pad on a prismatic joint (gripper_pad.rob) whose PID driver holds it 1 mm into
// the two padding layers (servoP 10000 N/m: about 10 N once the contact has pushed the overlap
// out); same probe and bars as the cube alone (the contact count now counts the pad's contacts
// too). Measured: at rest to 7e-15 m/s at 1 ms and 8e-16 m/s at 10 ms on 8 steady contacts (4 under
// the cube, 4 under the pad) under the exact solver, 2e-13 m/s under the Newton solver (bars met).
// QuickStep(20) does not hold it: the pressed cube rocks at 4.1 mm/s RMS at 1 ms with the contact
// count varying by 7 (the stress suite's gripper_pad cases); at 10 ms the pad's explicit PID
// would diverge (servoD·h/m = 5 on the 0.2 kg pad) and its actuator has no torque limit, so
// QuickStep solves that servo implicitly (explicit_pd.h): the cube rocks at 2 cm/s RMS (before
// 2026-11-29 the joint read -4e125 m with the status saying only "adaptive step").
#include <cmath>
#include <string>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scene_bars.h"
#include "core/accuracy/scenes.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

constexpr double kJitterDuration = 1.5;  // s
constexpr double kJitterSettle = 0.5;    // s before the measurement starts

class MeshJitterProbe : public AccuracyProbe {
 public:
  void Begin(const Simulator&) override {}
  void Observe(const StepEvent& event) override { watch_.Observe(event); }
  ProbeResult Finish(const Simulator& simulator) override {
    if (!watch_.Started()) return {kInf, {}, "shorter than the settling time"};
    ProbeResult result{watch_.RmsSpeed(), {{"RMS angular speed rad/s", watch_.RmsSpin()}}, ""};
    for (ProbeMetric& metric : watch_.Metrics(simulator)) result.metrics.push_back(metric);
    return result;
  }

 private:
  RestingWatch watch_{kJitterSettle};
};

}  // namespace

AccuracyScene MeshJitterScene(const std::string& variant) {
  AccuracyScene scene;
  scene.name = variant.empty() ? "mesh_jitter" : "mesh_jitter_" + variant;
  scene.world = scene.name + ".xml";
  const std::string padding = variant == "pad0"   ? "no padding"
                              : variant == "pad1" ? "1 mm padding"
                              : variant == "pad5" ? "5 mm padding"
                                                  : "2.5 mm padding";
  scene.title = "Mesh cube resting on a mesh floor" +
                (variant.empty() ? std::string() : " (" + padding + ")");
  scene.setup =
      "0.2 m, 1 kg mesh cube (12 triangles), turned 0.3 rad, on a two-triangle mesh "
      "floor across its diagonal, " +
      padding + "; 1.5 s";
  scene.metric = "RMS speed of the centre of mass after 0.5 s";
  scene.unit = "m/s";
  scene.answer = "0: at rest";
  scene.duration = kJitterDuration;
  scene.min_step = 1e-5;
  scene.probe = [](const WorldDesc&) { return std::make_unique<MeshJitterProbe>(); };
  if (variant == "pad0") {
    scene.bars = {
        {"the cube moves less than 1 mm at 1 ms and 10 ms", {1e-3, 1e-2}, [](const auto& runs) {
           return AtMost(runs, {"moved m", "mm", 1e3}, 1e-3);
         }}};
    return scene;
  }
  scene.bars = {
      {"RMS resting speed < 1e-3 m/s at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"", "m/s"}, 1e-3);
       }},
      {"contact count steady to within 1 over the last second at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"contact count range", "contacts"}, 1.0);
       }},
  };
  return scene;
}

AccuracyScene GripperPadScene() {
  AccuracyScene scene = MeshJitterScene("");
  scene.name = "gripper_pad";
  scene.world = "gripper_pad.xml";
  scene.title = "Gripper pad pressing a mesh cube on a mesh floor";
  scene.setup =
      "0.2 m, 1 kg mesh cube (12 triangles), turned 0.3 rad, on a two-triangle mesh floor, "
      "pressed from above by a 6 × 6 cm pad on a PID-held prismatic joint 1 mm into the 2.5 mm "
      "padding layers (about 10 N); 1.5 s";
  scene.answer = "0: at rest, pad and cube";
  return scene;
}

AccuracyScene ScannedTrayScene() {
  AccuracyScene scene;
  scene.name = "scanned_tray";
  scene.world = "scanned_tray.xml";
  scene.title = "Open tray with a scanned bottom resting on a mesh floor";
  scene.setup =
      "0.3 m, 0.5 kg open tray (no lid, 1344 triangles) whose bottom vertices are moved by up to "
      "0.3 mm, on a two-triangle mesh floor, 2.5 mm padding; 1.5 s";
  scene.metric = "RMS speed of the centre of mass after 0.5 s";
  scene.unit = "m/s";
  scene.answer = "0: at rest on its lowest bumps";
  scene.duration = kJitterDuration;
  scene.min_step = 1e-5;
  scene.probe = [](const WorldDesc&) { return std::make_unique<MeshJitterProbe>(); };
  scene.bars = MeshJitterScene("").bars;
  return scene;
}

}  // namespace lamina::core
