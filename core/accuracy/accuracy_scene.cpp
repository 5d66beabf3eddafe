// SPDX-License-Identifier: MIT
#include "core/accuracy/accuracy_scene.h"

#include "core/accuracy/scenes.h"

namespace lamina::core {

const std::vector<AccuracyScene>& AccuracyScenes() {
  static const std::vector<AccuracyScene> scenes = {
      BallisticBoxScene(), SlidingBlockScene(0.0), SlidingBlockScene(22.5), SlidingBlockScene(45.0),
      BouncingBallScene(), PendulumScene(),        InclineScene(),          SlideToRollScene(),
      BoxStackScene(),     HeavyOnLightScene(100), HeavyOnLightScene(1000), ChainScene(),
      StiffnessScene(),    HighSpeedScene(),       MeshJitterScene(),
  };
  return scenes;
}

std::optional<AccuracySolver> ParseAccuracySolver(const std::string& label) {
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
  if (!name.starts_with("quick") || name.size() == 5 || name.size() > 10) return std::nullopt;
  for (std::size_t i = 5; i < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9') return std::nullopt;
  }
  solver.type = SolverType::kQuickStep;
  solver.iterations = std::stoi(name.substr(5));
  if (solver.iterations < 1 || solver.iterations > 10000) return std::nullopt;
  return solver;
}

const AccuracyScene* FindAccuracyScene(const std::string& name) {
  for (const AccuracyScene& scene : AccuracyScenes()) {
    if (scene.name == name) return &scene;
  }
  return nullptr;
}

}  // namespace lamina::core
