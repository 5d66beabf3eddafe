// SPDX-License-Identifier: MIT
// Stiffness sweep (numerics §6 scene 10): three 10 cm, 1 kg rigid blocks rest on their own floor
// patches (object i on terrain i) whose layers have k = 1e4, 1e6 and 1e8 N/m at critical damping
// c = 2·√(k·m) (worlds/accuracy/stiffness.xml); 1 s. The pair's law is the blend of the two
// surfaces (a rigid block keeps the floor's k and c) turned into ODE's ERP/CFM for the step
// (core/contact/surface_blend.h: ERP = hk/(hk + c), CFM = 1/(hk + c)), the implicit-Euler
// spring-damper k·x − c·v; the pair pushes with k times its deepest layer overlap whatever the
// number of contacts (docs/contact-model.md, "Soft contacts"). So a resting block settles at the
// overlap δ = m·g/k (0.98 mm, 9.8 µm, 98 nm; all inside the 2.5 mm layer, so the rigid core under
// it never acts). k, c, m and g are read from the world.
//
// The probe reads each block's deepest layer overlap from the simulator's contacts at the end
// (the error: the largest relative error against m·g/k) and tracks each block's energy
// ½mv² + ½ωᵀIω − m·g·p + ½kδ² (the layer's spring included) while it is in contact; its largest
// rise above the lowest value before, relative to m·g·δ, is "energy growth". Counting starts in
// contact because the blocks are placed where their layers just touch, which is not yet a
// contact: they fall freely for the first step (g·h², 0.98 mm at 10 ms) and land deep in the
// stiff layers, a spring energy that no step released.
//
// Bars (numerics §6 scene 10): δ within 5 % of m·g/k at 1 ms and 10 ms, and no energy growth at
// 1 ms and 10 ms (allowance 1e-6·m·g·δ for rounding).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scene_bars.h"
#include "core/accuracy/scenes.h"
#include "core/contact/surface_blend.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

constexpr double kDuration = 1.0;  // s

struct SoftBlock {
  std::string name;
  double stiffness = 0.0;              // N/m, the pair's
  double expected = 0.0;               // m·g/k, m
  double lowest = kInf, growth = 0.0;  // J: lowest energy in contact so far, largest rise since
};

std::vector<SoftBlock> ReadBlocks(const WorldDesc& world) {
  std::vector<SoftBlock> blocks;
  const double g = world.settings.gravity.norm();
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const RigidObjectDesc& object = world.objects[i];
    const double k = BlendSurfaces(object.sim.surface, world.terrains.at(i).sim.surface).stiffness;
    blocks.push_back({object.name, k, object.mass * g / k});
  }
  return blocks;
}

// Deepest layer overlap of object `object` with anything, m (0 without contact).
double Overlap(const Simulator& simulator, const std::vector<ContactPair>& pairs, int object) {
  const int id = simulator.world().ObjectId(object);
  double depth = 0.0;
  for (const ContactPair& pair : pairs) {
    if (pair.a == id || pair.b == id) depth = std::max(depth, pair.max_depth);
  }
  return depth;
}

// Kinetic plus gravitational energy of one object, J.
double MotionEnergy(const Simulator& simulator, int object) {
  const RigidObjectDesc& desc = simulator.world().objects.at(object);
  const Vec3 v = ObjectComVelocity(simulator, object);
  const Vec3 l = ObjectAngularMomentum(simulator, object);
  const Vec3 w = simulator.GetObjectVelocity(object).angular;
  const double height = -simulator.world().settings.gravity.dot(ObjectCom(simulator, object));
  return 0.5 * desc.mass * v.squaredNorm() + 0.5 * w.dot(l) + desc.mass * height;
}

class StiffnessProbe : public AccuracyProbe {
 public:
  explicit StiffnessProbe(const WorldDesc& world) : blocks_(ReadBlocks(world)) {}
  void Begin(const Simulator&) override {}
  void Observe(const StepEvent& event) override {
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      const int object = static_cast<int>(i);
      if (Overlap(event.simulator, event.contacts, object) <= 0.0) continue;
      SoftBlock& block = blocks_[i];
      const double e = Energy(event.simulator, event.contacts, object);
      block.growth = std::max(block.growth, e - block.lowest);
      block.lowest = std::min(block.lowest, e);
    }
  }
  ProbeResult Finish(const Simulator& simulator) override {
    ProbeResult result;
    double growth = 0.0;
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      const SoftBlock& block = blocks_[i];
      const double depth = Overlap(simulator, simulator.contact_pairs(), static_cast<int>(i));
      result.error = std::max(result.error, std::abs(depth - block.expected) / block.expected);
      result.metrics.push_back({block.name + " overlap m", depth});
      growth = std::max(growth, block.growth / StaticEnergy(block));
    }
    result.metrics.push_back({"energy growth", growth});
    return result;
  }

 private:
  double Energy(const Simulator& simulator, const std::vector<ContactPair>& pairs,
                int object) const {
    const double depth = Overlap(simulator, pairs, object);
    return MotionEnergy(simulator, object) + 0.5 * blocks_[object].stiffness * depth * depth;
  }
  // m·g·δ: the energy scale of settling into the layer, J.
  static double StaticEnergy(const SoftBlock& block) {
    return block.stiffness * block.expected * block.expected;
  }
  std::vector<SoftBlock> blocks_;
};

}  // namespace

AccuracyScene StiffnessScene() {
  AccuracyScene scene;
  scene.name = "stiffness";
  scene.world = "stiffness.xml";
  scene.title = "Blocks resting on soft layers, k = 1e4, 1e6, 1e8 N/m";
  scene.setup =
      "three 10 cm, 1 kg rigid blocks on floor patches with k = 1e4, 1e6, 1e8 N/m at "
      "critical damping c = 2√(km); 1 s";
  scene.metric = "largest relative error of the resting overlap against m·g/k";
  scene.unit = "";
  scene.answer = "δ = m·g/k = 0.98 mm, 9.8 µm, 98 nm; no energy growth";
  scene.duration = kDuration;
  scene.min_step = 1e-5;
  scene.probe = [](const WorldDesc& world) { return std::make_unique<StiffnessProbe>(world); };
  scene.bars = {
      {"resting overlap within 5 % of m·g/k for every k at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"", "%", 100.0}, 0.05);
       }},
      {"no energy growth (≤ 1e-6·m·g·δ) at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"energy growth", "m·g·δ"}, 1e-6);
       }},
  };
  return scene;
}

}  // namespace lamina::core
