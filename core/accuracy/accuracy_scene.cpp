// SPDX-License-Identifier: MIT
#include "core/accuracy/accuracy_scene.h"

#include "core/accuracy/scenes.h"

namespace lamina::core {

const std::vector<AccuracyScene>& AccuracyScenes() {
  static const std::vector<AccuracyScene> scenes = {
      BallisticBoxScene(),
      SlidingBlockScene(0.0),
      SlidingBlockScene(22.5),
      SlidingBlockScene(45.0),
      BouncingBallScene("0.5"),
      BouncingBallScene("0.9"),
      BouncingBallScene("1"),
      BouncingBallsScene(),  // SimBenchmark's bouncing
      PendulumScene(),
      LinkedPendulumScene(2),
      LinkedPendulumScene(10),
      InclineScene(),
      SlideToRollScene(false),
      SlideToRollScene(true),
      BoxStackScene(),
      PyramidScene(),     // Solver2D's pyramid
      SpherePileScene(),  // SimBenchmark's 666
      KaplaScene(),       // SimBenchmark's Kapla
      HeavyOnLightScene(100),
      HeavyOnLightScene(1000),
      ChainScene(),
      BridgeScene(),  // Solver2D's bridge
      StiffnessScene(),
      StiffnessDropScene(),
      HighSpeedScene(false),
      HighSpeedScene(true),
      MeshJitterScene(""),
      MeshJitterScene("pad0"),
      MeshJitterScene("pad1"),
      MeshJitterScene("pad5"),
      GripperPadScene(),  // numerics' gripper pad pressing a mesh
      ScannedTrayScene(),
      SoftBallScene(4),
      SoftBallScene(20),
      SoftBallScene(100),
  };
  return scenes;
}

namespace {

// The iterations after `prefix` in `name` ("quick40" -> 40); nullopt unless 1 … 10000.
std::optional<int> IterationsAfter(const std::string& name, const std::string& prefix) {
  if (!name.starts_with(prefix) || name.size() == prefix.size()) return std::nullopt;
  if (name.size() > prefix.size() + 5) return std::nullopt;
  for (std::size_t i = prefix.size(); i < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9') return std::nullopt;
  }
  const int iterations = std::stoi(name.substr(prefix.size()));
  if (iterations < 1 || iterations > 10000) return std::nullopt;
  return iterations;
}

std::optional<AccuracySolver> ParsePeer(const std::string& name) {
  AccuracySolver solver;
  if (name == "mujoco") {
    solver.peer = name;
    return solver;
  }
  const std::optional<int> iterations = IterationsAfter(name, "bullet");
  if (!iterations) return std::nullopt;
  solver.peer = "bullet";
  solver.iterations = *iterations;
  return solver;
}

}  // namespace

std::optional<AccuracySolver> ParseAccuracySolver(const std::string& label) {
  if (const std::optional<AccuracySolver> peer = ParsePeer(label)) return peer;
  AccuracySolver solver;
  std::string name = label;
  const std::string fixed = "-fixed";
  if (name.size() > fixed.size() && name.ends_with(fixed)) {
    solver.adaptive = false;
    name.resize(name.size() - fixed.size());
  }
  if (name == "exact") return solver;
  if (name == "newton") {
    solver.type = SolverType::kNewton;
    return solver;
  }
  const std::optional<int> iterations = IterationsAfter(name, "quick");
  if (!iterations) return std::nullopt;
  solver.type = SolverType::kQuickStep;
  solver.iterations = *iterations;
  return solver;
}

const AccuracyScene* FindAccuracyScene(const std::string& name) {
  for (const AccuracyScene& scene : AccuracyScenes()) {
    if (scene.name == name) return &scene;
  }
  return nullptr;
}

}  // namespace lamina::core
