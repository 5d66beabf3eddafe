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
//
// The drop (stiffness_drop.xml): four such blocks fall from 0.1 m onto layers of k = 1e5, 1e6,
// 1e8 and 1e9 N/m at critical damping; 0.3 s. Each lands at v₀ = √(2·g·0.1) = 1.4 m/s and the
// layer's overlap x follows m·x'' = m·g − k·x − c·x' from x = 0, x' = v₀ until the layer's force
// k·x + c·x' falls to 0 on the way out: a contact pushes and never pulls, so the block lets go
// there, still rising (at 0.13·v₀: a unilateral spring-damper rebounds even at critical damping),
// and flies up to −x + x'²/(2g) above the layer. The answer is that equation integrated by RK4 at
// 1/(1000·ω) (ω = √(k/m)): peak overlaps 1.655 mm, 0.518 mm, 51.5 µm, 16.3 µm (all inside the
// 2.5 mm layer) and rebounds 0.486, 1.402, 1.789, 1.818 mm. The probe keeps each block's deepest
// overlap and, after it landed, the highest its padded bottom rose above the layer; the error is
// the largest relative error of the peaks.
//
// ODE's spring-damper is implicit Euler (ERP, CFM), stable at any h, and a contact starts only
// once the layers overlap, up to v₀·h deep (1.4 mm at 1 ms). So the answers converge at first
// order once h ≪ 1/ω (1/ω = 3.2 ms, 1 ms, 0.1 ms, 32 µs); with h ≳ 1/ω the block lands deep in a
// stiff layer, which throws it back (3.6 cm at 1 ms on k = 1e9). Bars: the soft layers (k = 1e5,
// 1e6) within 2 % at 10 µs, both peak and rebound; no correction or non-finite state at 1 and 10
// ms.
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

constexpr double kStiffnessDuration = 1.0;  // s

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
      if (ObjectLayerOverlap(event.simulator, event.contacts, object) <= 0.0) continue;
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
      const double depth =
          ObjectLayerOverlap(simulator, simulator.contact_pairs(), static_cast<int>(i));
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
    const double depth = ObjectLayerOverlap(simulator, pairs, object);
    return MotionEnergy(simulator, object) + 0.5 * blocks_[object].stiffness * depth * depth;
  }
  // m·g·δ: the energy scale of settling into the layer, J.
  static double StaticEnergy(const SoftBlock& block) {
    return block.stiffness * block.expected * block.expected;
  }
  std::vector<SoftBlock> blocks_;
};

// Height of object `object`'s padded bottom above its terrain's padded top, m (boxes).
double DropHeight(const WorldDesc& world, int object) {
  const RigidObjectDesc& block = world.objects.at(object);
  const TerrainDesc& floor = world.terrains.at(object);
  const Affine box = block.geometry.Matrix() * block.geometry.primitive.pose;
  const Affine patch = floor.geometry.Matrix() * floor.geometry.primitive.pose;
  const double bottom = (block.pose * box).translation().z() -
                        0.5 * block.geometry.primitive.size.z() - block.sim.padding;
  const double top =
      patch.translation().z() + 0.5 * floor.geometry.primitive.size.z() + floor.sim.padding;
  return bottom - top;
}

// m·x'' = m·g − k·x − c·x' from x = 0, x' = v0 while the layer pushes (RK4): the first maximum of
// x, and how high (m) above the layer the block flies once it lets go.
struct LayerAnswer {
  double peak = 0.0, rebound = 0.0;
};

LayerAnswer SpringDamperLanding(double m, double k, double c, double g, double v0) {
  const double dt = 1e-3 / std::sqrt(k / m);
  auto acceleration = [&](double x, double v) { return g - (k * x + c * v) / m; };
  double x = 0.0, v = v0;
  LayerAnswer answer;
  for (int i = 0; i < 100000000 && x >= 0.0 && k * x + c * v > 0.0; ++i) {
    const double a1 = acceleration(x, v);
    const double a2 = acceleration(x + 0.5 * dt * v, v + 0.5 * dt * a1);
    const double a3 = acceleration(x + 0.5 * dt * (v + 0.5 * dt * a1), v + 0.5 * dt * a2);
    const double a4 = acceleration(x + dt * (v + 0.5 * dt * a2), v + dt * a3);
    x += dt * (v + dt * (a1 + a2 + a3) / 6.0);
    v += dt * (a1 + 2.0 * a2 + 2.0 * a3 + a4) / 6.0;
    answer.peak = std::max(answer.peak, x);
  }
  answer.rebound = v < 0.0 ? -x + v * v / (2.0 * g) : -x;
  return answer;
}

struct DropBlock {
  std::string name;
  LayerAnswer expected;
  double drop = 0.0;     // initial height of the padded bottom above the layer, m
  double start_z = 0.0;  // initial COM height, m
  LayerAnswer seen;      // the deepest overlap; the highest rise above the layer after landing
  bool landed = false;
};

std::vector<DropBlock> ReadDrops(const WorldDesc& world) {
  std::vector<DropBlock> drops;
  const double g = world.settings.gravity.norm();
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const RigidObjectDesc& object = world.objects[i];
    const BlendedSurface layer =
        BlendSurfaces(object.sim.surface, world.terrains.at(i).sim.surface);
    const double drop = DropHeight(world, static_cast<int>(i));
    const double v0 = std::sqrt(2.0 * g * drop);
    DropBlock block;
    block.name = object.name;
    block.expected = SpringDamperLanding(object.mass, layer.stiffness, layer.damping, g, v0);
    block.drop = drop;
    block.start_z = (object.pose * object.com).z();
    drops.push_back(block);
  }
  return drops;
}

class StiffnessDropProbe : public AccuracyProbe {
 public:
  explicit StiffnessDropProbe(const WorldDesc& world) : drops_(ReadDrops(world)) {}
  void Begin(const Simulator&) override {}
  void Observe(const StepEvent& event) override {
    for (std::size_t i = 0; i < drops_.size(); ++i) {
      const int object = static_cast<int>(i);
      DropBlock& drop = drops_[i];
      const double depth = ObjectLayerOverlap(event.simulator, event.contacts, object);
      drop.landed = drop.landed || depth > 0.0;
      drop.seen.peak = std::max(drop.seen.peak, depth);
      const double height = ObjectCom(event.simulator, object).z() - drop.start_z + drop.drop;
      if (drop.landed) drop.seen.rebound = std::max(drop.seen.rebound, height);
    }
  }
  ProbeResult Finish(const Simulator&) override {
    ProbeResult result;
    for (const DropBlock& drop : drops_) {
      const double peak = Relative(drop.seen.peak, drop.expected.peak);
      const double rebound = Relative(drop.seen.rebound, drop.expected.rebound);
      result.error = std::max(result.error, peak);
      result.metrics.push_back({drop.name + " peak m", drop.seen.peak});
      result.metrics.push_back({drop.name + " peak error", peak});
      result.metrics.push_back({drop.name + " rebound m", drop.seen.rebound});
      result.metrics.push_back({drop.name + " rebound error", rebound});
    }
    return result;
  }

 private:
  static double Relative(double value, double expected) {
    return std::abs(value - expected) / expected;
  }
  std::vector<DropBlock> drops_;
};

// The soft layers' peak and rebound errors at most 2 %.
BarCheck SoftLayersWithin(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check{true, ""};
  for (const char* block : {"block_k1e5", "block_k1e6"}) {
    for (const char* what : {" peak error", " rebound error"}) {
      const BarCheck one = AtMost(runs, {std::string(block) + what, "%", 100.0}, 0.02);
      check.pass = check.pass && one.pass;
      check.measured +=
          (check.measured.empty() ? "" : "; ") + std::string(block) + what + " " + one.measured;
    }
  }
  return check;
}

}  // namespace

AccuracyScene StiffnessDropScene() {
  AccuracyScene scene;
  scene.name = "stiffness_drop";
  scene.world = "stiffness_drop.xml";
  scene.title = "Blocks dropped 0.1 m onto soft layers, k = 1e5, 1e6, 1e8, 1e9 N/m";
  scene.setup =
      "four 10 cm, 1 kg rigid blocks dropped from 0.1 m onto floor patches with k = 1e5, 1e6, "
      "1e8, 1e9 N/m at critical damping c = 2√(km); 0.3 s";
  scene.metric = "largest relative error of the peak overlap against the spring-damper's";
  scene.unit = "";
  scene.answer =
      "peak overlap 1.655 mm, 0.518 mm, 51.5 µm, 16.3 µm; rebound 0.486, 1.402, 1.789, 1.818 mm "
      "above the layer";
  scene.duration = 0.3;
  scene.min_step = 1e-5;
  scene.probe = [](const WorldDesc& world) { return std::make_unique<StiffnessDropProbe>(world); };
  scene.bars = {
      {"peak overlap and rebound within 2 % for k = 1e5 and 1e6 at 10 µs",
       {1e-5},
       SoftLayersWithin},
      {"no correction or non-finite state at 1 ms and 10 ms", {1e-3, 1e-2}, Stable},
  };
  return scene;
}

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
  scene.duration = kStiffnessDuration;
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
