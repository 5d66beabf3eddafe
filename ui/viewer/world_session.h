// SPDX-License-Identifier: MIT
// The world the viewer shows: the loaded description, its simulation, and the poses drawn (the
// simulation's current state, taken after every Advance, AdvanceTime and Reset). The description
// stays as loaded: runtime state never goes into it (what would be saved is not the current
// frame), and the viewer draws description + poses. A world that fails to load leaves the
// previous one in place and keeps the messages for the World panel; nothing here throws.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/diagnostics.h"
#include "core/model/world_desc.h"
#include "core/render/world_poses.h"
#include "core/sim/simulator.h"

namespace lamina::ui {

class WorldSession {
 public:
  WorldSession();
  ~WorldSession();

  /// Loads `path` and builds its simulation (contact feedback on, for the overlays). False when
  /// it fails; the previous world (if any) stays and `load_messages()` says why.
  /// `sets` are --set PATH=VALUE arguments applied to the loaded description first (access
  /// paths, docs/access-paths.md); a refused one fails the load, naming it.
  bool Load(const std::string& path, const std::vector<std::string>& sets = {});
  bool loaded() const { return simulator_ != nullptr; }

  /// Advances the simulation by `steps` physics steps; the simulated seconds it took.
  double Advance(int steps);
  /// Advances by `seconds` at once (the --time option, like `shot --time`).
  void AdvanceTime(double seconds);
  /// Back to time 0 and the world's initial state.
  void Reset();
  void SetSolver(core::SolverType type);
  void SetSleeping(bool on);

  /// The world as loaded (its initial conditions; never the current state).
  const core::WorldDesc& description() const { return description_; }
  /// Where the simulation has the bodies now: object frames and robot configurations.
  const core::WorldPoses& poses() const { return poses_; }
  const core::Simulator* simulator() const { return simulator_.get(); }
  const std::string& path() const { return path_; }
  /// Diagnostics of the world loaded last (warnings of a good load, errors of a failed one).
  const core::Diagnostics& load_messages() const { return diagnostics_; }
  /// Status of the last simulated step.
  core::StepStatus last_status() const { return last_status_; }

 private:
  void TakePoses();

  core::WorldDesc description_;
  core::WorldPoses poses_;
  std::unique_ptr<core::Simulator> simulator_;
  core::Diagnostics diagnostics_;
  std::string path_;
  core::StepStatus last_status_ = core::StepStatus::kNormal;
};

}  // namespace lamina::ui
