// SPDX-License-Identifier: MIT
#include "ui/viewer/world_session.h"

#include <exception>
#include <filesystem>

#include "core/io/world_file.h"
#include "core/model/access_path.h"

namespace lamina::ui {

WorldSession::WorldSession() = default;
WorldSession::~WorldSession() = default;

namespace {

// the --set arguments on a loaded description; false with an error naming the argument
bool ApplySets(const std::string& path, const std::vector<std::string>& sets,
               core::Diagnostics* diagnostics, core::WorldDesc* world) {
  for (const std::string& set : sets) {
    std::string target, value, error;
    if (!core::SplitAssignment(set, &target, &value, &error) ||
        !core::SetPathText(world, target, value, &error)) {
      diagnostics->Error({path, 0}, "--set '" + set + "': " + error);
      return false;
    }
  }
  return true;
}

}  // namespace

bool WorldSession::Load(const std::string& requested_path, const std::vector<std::string>& sets) {
  std::error_code path_error;
  std::string path = std::filesystem::weakly_canonical(requested_path, path_error).string();
  if (path_error || path.empty()) path = requested_path;
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  core::WorldDesc world;
  std::unique_ptr<core::Simulator> simulator;
  try {
    if (!std::filesystem::is_regular_file(path)) {
      diagnostics.Error({path, 0}, "no such file");
    } else if (core::LoadWorldFile(path, context, &world) && !diagnostics.HasErrors() &&
               ApplySets(path, sets, &diagnostics, &world)) {
      simulator = std::make_unique<core::Simulator>(world);
      simulator->EnableContactFeedbackAll();
    }
  } catch (const std::exception& error) {
    diagnostics.Error({path, 0}, std::string("cannot build the simulation: ") + error.what());
    simulator.reset();
  }
  diagnostics_ = std::move(diagnostics);
  if (!simulator) return false;
  description_ = std::move(world);
  simulator_ = std::move(simulator);
  path_ = path;
  last_status_ = core::StepStatus::kNormal;
  TakePoses();
  return true;
}

double WorldSession::Advance(int steps) {
  if (!simulator_ || steps <= 0) return 0.0;
  const double before = simulator_->time();
  last_status_ = simulator_->Simulate(steps * simulator_->sim_step());
  TakePoses();
  return simulator_->time() - before;
}

void WorldSession::AdvanceTime(double seconds) {
  if (!simulator_ || !(seconds > 0.0)) return;
  last_status_ = simulator_->Simulate(seconds);
  TakePoses();
}

void WorldSession::Reset() {
  if (!simulator_) return;
  simulator_->Reset();
  last_status_ = core::StepStatus::kNormal;
  TakePoses();
}

void WorldSession::SetSolver(core::SolverType type) {
  if (!simulator_) return;
  core::SolverSettings solver = simulator_->solver();
  solver.type = type;
  simulator_->SetSolver(solver);
}

void WorldSession::SetSleeping(bool on) {
  if (simulator_) simulator_->SetSleeping(on);
}

void WorldSession::TakePoses() {
  poses_ = core::CurrentPoses(*simulator_);
}

}  // namespace lamina::ui
