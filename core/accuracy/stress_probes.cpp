// SPDX-License-Identifier: MIT
#include "core/accuracy/stress_probes.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geometry/triangle_mesh.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

class FloorGapProbe : public AccuracyProbe {
 public:
  FloorGapProbe(const WorldDesc& world, double floor) : floor_(floor) {
    for (const RigidObjectDesc& object : world.objects) {
      meshes_.push_back(BakedMesh(object.geometry));
      padding_ = std::min(padding_, object.sim.padding);
    }
  }
  void Begin(const Simulator&) override {}
  void Observe(const StepEvent& event) override {
    lowest_ = std::min(lowest_, Lowest(event.simulator));
  }
  ProbeResult Finish(const Simulator& simulator) override {
    const double final_gap = Lowest(simulator);
    ProbeResult result{std::min(lowest_, final_gap), {}, ""};
    result.metrics = {{"final lowest core m", final_gap}, {"padding m", padding_}};
    if (result.error < 0.0) result.note = "a core went below the floor";
    return result;
  }

 private:
  // the lowest core point of every object above the floor now, m
  double Lowest(const Simulator& simulator) const {
    double lowest = kInf;
    for (std::size_t i = 0; i < meshes_.size(); ++i) {
      const Pose pose = simulator.GetObjectPose(static_cast<int>(i));
      for (const Vec3& vertex : meshes_[i].vertices) {
        lowest = std::min(lowest, (pose * vertex).z() - floor_);
      }
    }
    return lowest;
  }

  double floor_;
  std::vector<TriangleMesh> meshes_;
  double padding_ = kInf;
  double lowest_ = kInf;
};

class JointGapProbe : public AccuracyProbe {
 public:
  explicit JointGapProbe(const WorldDesc& world) : robot_(world.robots.at(0)) {}
  void Begin(const Simulator& simulator) override { start_ = Origins(simulator); }
  void Observe(const StepEvent& event) override {
    largest_ = std::max(largest_, Gap(event.simulator));
  }
  ProbeResult Finish(const Simulator& simulator) override {
    const std::vector<Vec3> origins = Origins(simulator);
    double moved = 0.0;
    for (std::size_t l = 0; l < origins.size(); ++l) {
      moved = std::max(moved, (origins[l] - start_[l]).norm());
    }
    const double gap = Gap(simulator);
    ProbeResult result{std::max(largest_, gap), {}, ""};
    result.metrics = {
        {"final joint gap m", gap},
        {"largest link displacement m", moved},
        {"largest joint speed rad/s", simulator.GetRobotVelocity(0).cwiseAbs().maxCoeff()}};
    return result;
  }

 private:
  std::vector<Pose> Frames(const Simulator& simulator) const {
    std::vector<Pose> frames;
    // SimBody's getters do not change the simulation; it is handed out by the non-const body()
    Simulator& readable = const_cast<Simulator&>(simulator);
    for (int l = 0; l < robot_.dof(); ++l) {
      frames.push_back(readable.body(simulator.world().RobotLinkId(0, l)).GetTransform());
    }
    return frames;
  }
  std::vector<Vec3> Origins(const Simulator& simulator) const {
    std::vector<Vec3> origins;
    for (const Pose& frame : Frames(simulator)) origins.push_back(frame.translation());
    return origins;
  }
  // the largest distance of a link's origin from where its parent puts it, m
  double Gap(const Simulator& simulator) const {
    const std::vector<Pose> frames = Frames(simulator);
    double gap = 0.0;
    for (int l = 0; l < robot_.dof(); ++l) {
      const int parent = robot_.links[l].parent;
      if (parent < 0) continue;
      const Vec3 expected = frames[parent] * robot_.links[l].parent_transform.translation();
      gap = std::max(gap, (frames[l].translation() - expected).norm());
    }
    return gap;
  }

  RobotDesc robot_;  // a copy: the probe may outlive the description it was made from
  std::vector<Vec3> start_;
  double largest_ = 0.0;
};

}  // namespace

std::unique_ptr<AccuracyProbe> MakeFloorGapProbe(const WorldDesc& world, double floor) {
  return std::make_unique<FloorGapProbe>(world, floor);
}

std::unique_ptr<AccuracyProbe> MakeJointGapProbe(const WorldDesc& world) {
  return std::make_unique<JointGapProbe>(world);
}

}  // namespace lamina::core
