// SPDX-License-Identifier: MIT
// The live accuracy meter's step doubling (error_meter.h): the coming step taken whole and in
// halves from the same state, with everything a step changes besides the state (statistics,
// feedback, interaction, observers, camera pictures) kept out or put back.
#include <utility>

#include <ode/ode.h>

#include "core/sim/ode_conversions.h"
#include "core/sim/sim_timing.h"
#include "core/sim/simulator.h"

namespace lamina::core {

void Simulator::SetErrorMeter(bool on) {
  meter_on_ = on;
  meter_.Reset();
}

// the origins of the ODE bodies that move freely (objects and robot links), in table order
std::vector<Vec3> Simulator::MovingBodyPositions() const {
  std::vector<Vec3> positions;
  for (const BodyRecord& record : bodies_) {
    if (record.moves_freely() && record.owns_body) {
      const dReal* p = dBodyGetPosition(record.body);
      positions.emplace_back(p[0], p[1], p[2]);
    }
  }
  return positions;
}

// from `start`, the steps in turn; false when one failed (the simulation then halted)
bool Simulator::ProbeSteps(const SimState& start, const std::vector<double>& steps,
                           std::vector<Vec3>* positions) {
  SetState(start);
  for (double h : steps) {
    if (Step(h) == StepStatus::kError) return false;
  }
  *positions = MovingBodyPositions();
  return true;
}

void Simulator::SampleStepError(double step) {
  Stopwatch watch;
  const SimState start = GetState();
  const SimStatistics statistics = statistics_;
  std::vector<ContactFeedbackRecord> feedback = feedback_.records();
  const DragState drag = drag_;
  const std::map<int, KinematicTarget> targets = targets_;
  // the energy check's references, which SetState forgets, and which bodies took gravity's kick
  std::vector<double> energies;
  std::vector<bool> kicked;
  for (const BodyRecord& record : bodies_) {
    energies.push_back(record.energy);
    kicked.push_back(record.kicked);
  }
  CameraRenderer* const renderer = camera_renderer_;
  camera_renderer_ = nullptr;
  probing_ = true;
  std::vector<Vec3> full, halves;
  const bool ok =
      ProbeSteps(start, {step}, &full) && ProbeSteps(start, {step / 2, step / 2}, &halves);
  probing_ = false;
  camera_renderer_ = renderer;
  SetState(start);  // (rebuilds a simulation a probe step halted)
  statistics_ = statistics;
  feedback_.RestoreRecords(std::move(feedback));
  drag_ = drag;
  targets_ = targets;
  std::size_t i = 0;
  for (BodyRecord& record : bodies_) {
    record.energy = energies[i];
    record.kicked = kicked[i++];
  }
  if (ok) {
    meter_.Add(MakeStepErrorSample(time_, step, full, halves), watch.Lap());
  } else {
    meter_.AddSamplingTime(watch.Lap());
  }
}

}  // namespace lamina::core
