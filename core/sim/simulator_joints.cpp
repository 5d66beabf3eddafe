// SPDX-License-Identifier: MIT
// The Simulator's world joints in maximal coordinates: the drift a step leaves in them taken back
// (joint_stabilization.h; the world's `jointStabilization`).
#include <algorithm>

#include <ode/ode.h>

#include "core/sim/ode_conversions.h"
#include "core/sim/simulator.h"

namespace lamina::core {

namespace {

// a drift that needs no correction (m): 0.1 nm
constexpr double kStabilizedGap = 1e-10;

// a robot's link stays where its robot's step put it (its own joints hold it there), as does a
// body ODE does not move (kinematic, asleep)
StabilizedBody StabilizedOf(dBodyID body, bool object) {
  StabilizedBody stabilized;
  stabilized.start = ReadBodyState(body);
  stabilized.moves = object && dBodyIsEnabled(body) != 0 && dBodyIsKinematic(body) == 0;
  dMass mass;
  dBodyGetMass(body, &mass);
  stabilized.mass = mass.mass;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) stabilized.inertia(r, c) = mass.I[4 * r + c];
  }
  return stabilized;
}

// the index of `body` in `ids`, added (with its state in `bodies`) when it is not there yet
int StabilizedIndex(dBodyID body, bool object, std::vector<dBodyID>* ids,
                    std::vector<StabilizedBody>* bodies) {
  const auto found = std::find(ids->begin(), ids->end(), body);
  if (found != ids->end()) return static_cast<int>(found - ids->begin());
  ids->push_back(body);
  bodies->push_back(StabilizedOf(body, object));
  return static_cast<int>(ids->size()) - 1;
}

}  // namespace

// before the step: every world joint ODE will hold in it (not one the Newton solver took in
// joint coordinates: ProjectReducedWorldJoints places those), its bodies as the joints list them
// (the stabilizer's profile follows that order: a chain listed end to end is a band) with their
// poses at the start
void Simulator::PrepareJointStabilization() {
  std::vector<dBodyID>& ids = stabilized_ids_;
  std::vector<StabilizedBody>& bodies = stabilized_bodies_;
  std::vector<StabilizedJoint>& joints = stabilized_joints_;
  ids.clear();
  bodies.clear();
  joints.clear();
  if (!world_.settings.joint_stabilization) return;
  for (int j = 0; j < world_joints_.size(); ++j) {
    dJointID joint = world_joints_.ode_joint(j);
    // (a joint whose first body is the world has no placement: world_joints.h)
    if (joint == nullptr || dJointGetBody(joint, 0) == nullptr) continue;
    if (islands_active_ && islands_.SolvedReduced(joint)) continue;
    const std::vector<WorldJointBody>& desc = world_.joints[static_cast<size_t>(j)].bodies;
    const auto object = [&](size_t i) { return desc[i].kind == WorldId::Kind::kRigidObject; };
    StabilizedJoint stabilized;
    stabilized.child = StabilizedIndex(dJointGetBody(joint, 0), object(0), &ids, &bodies);
    dBodyID parent = dJointGetBody(joint, 1);
    stabilized.parent = parent != nullptr ? StabilizedIndex(parent, object(1), &ids, &bodies) : -1;
    stabilized.placement = world_joints_.placement(j, true);
    joints.push_back(stabilized);
  }
}

// after the step: the drift it left taken back (the bodies moved, their velocities changed)
void Simulator::StabilizeWorldJoints(double step) {
  if (stabilized_joints_.empty()) return;
  for (size_t b = 0; b < stabilized_ids_.size(); ++b) {
    stabilized_bodies_[b].state = ReadBodyState(stabilized_ids_[b]);
  }
  stabilizer_.Stabilize(&stabilized_bodies_, stabilized_joints_, step, world_.settings.erp,
                        kStabilizedGap);
  for (size_t b = 0; b < stabilized_ids_.size(); ++b) {
    if (stabilized_bodies_[b].moves)
      WriteBodyState(stabilized_ids_[b], stabilized_bodies_[b].state);
  }
}

}  // namespace lamina::core
