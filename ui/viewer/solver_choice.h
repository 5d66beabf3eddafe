// SPDX-License-Identifier: MIT
// The editor's real-time solver choice. While a world plays with ODE's exact solver
// (dWorldStep), the cost of its steps is measured: wall seconds spent stepping per simulated
// second. Once kEvidence simulated seconds show that keeping up with the wall clock (times
// the playback speed) would take more than kPhysicsBudget of one core, the editor runs the world
// with the Newton solver instead and says so (it takes objects and robots, with the exact
// solver's answer: stacks, mass ratios and standing humanoids still hold; bodies held by world
// joints stay with dWorldStep inside it); the world's own
// setting is left as it is (the file keeps what it says, and saving writes it unchanged). On
// rough ground a humanoid's contacts and joint friction can take the Newton solver more steps
// than dWorldStep's pivots (docs/simulator.md): it then plays no faster, but still holds, where
// QuickStep would tip it over.
//
// Why a budget below one core: the physics has its own thread, but on a two-core machine with a
// software renderer the rasterizer needs the other core and part of this one (llvmpipe draws
// with two threads); a physics thread that is busy all the time makes every frame slower.
//
// The choice is one-way for a world: after it, nothing measures the exact solver any more, so
// the editor never flips between solvers; the user goes back with "use the world's solver" (or
// by choosing a solver in the settings, which is their decision). MuJoCo's simulate has no such
// choice and shows the real-time factor only; Klamp't always uses dWorldStep.
#pragma once

namespace lamina::ui {

class SolverChoice {
 public:
  /// Share of one core the physics may take to keep real time (wall s per simulated s x speed).
  static constexpr double kPhysicsBudget = 0.8;

  explicit SolverChoice(double budget = kPhysicsBudget) : budget_(budget) {}
  /// Simulated seconds measured before deciding.
  static constexpr double kEvidence = 0.5;

  /// `wall` seconds spent stepping gave `simulated` seconds at playback `speed` (> 0).
  void Add(double wall, double simulated, double speed);
  /// True once the measured cost exceeds the budget (and stays true until Clear).
  bool too_slow() const { return too_slow_; }
  /// Measured wall seconds per simulated second (0 before any measurement).
  double cost() const { return simulated_ > 0.0 ? wall_ / simulated_ : 0.0; }
  /// The real-time factor the exact solver could reach with the whole core: 1 / cost.
  double reachable_factor() const { return cost() > 0.0 ? 1.0 / cost() : 0.0; }
  void Clear() { *this = SolverChoice(budget_); }
  double budget() const { return budget_; }

 private:
  double budget_;
  double wall_ = 0.0, simulated_ = 0.0, speed_ = 1.0;
  bool too_slow_ = false;
};

}  // namespace lamina::ui
