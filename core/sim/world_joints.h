// SPDX-License-Identifier: MIT
// The world-level joints of a world (WorldJointDesc: `<simulation><joint>`) as ODE joints
// between the bodies the simulator built: fixed, hinge and slider, with their limits as ODE
// stops and their friction as a zero-velocity motor whose force limit is the friction (as
// Klamp't's ODEJoint). A terrain, or a link welded to the world, stands for the world.
// Positions count from the pose the bodies had when the joints were built: the world's initial
// poses (the simulator builds them there), so a hinge reads 0 rad and a slider 0 m at the start.
#pragma once

#include <functional>
#include <vector>

#include "core/diagnostics.h"
#include "core/model/world_desc.h"
#include "core/sim/joint_projection.h"
#include "core/sim/ode_fwd.h"
#include "core/sim/ode_joint_rows.h"

namespace lamina::core {

class OdeWorldJoints {
 public:
  OdeWorldJoints() = default;
  OdeWorldJoints(const OdeWorldJoints&) = delete;
  OdeWorldJoints& operator=(const OdeWorldJoints&) = delete;
  ~OdeWorldJoints() { Clear(); }

  /// The ODE body of a joint's body (null: the world).
  using BodyOf = std::function<dxBody*(const WorldJointBody&)>;
  /// Builds world.joints in `ode_world` with the bodies where they are now. A joint whose
  /// bodies are all static is skipped with a warning (it holds nothing that moves).
  void Build(dxWorld* ode_world, const WorldDesc& world, const BodyOf& body_of,
             Diagnostics& diagnostics);
  /// Destroys the joints (before the ODE world or the bodies go).
  void Clear();

  int size() const { return static_cast<int>(joints_.size()); }
  /// Joint `joint` of world.joints: the hinge angle (rad) or slider travel (m) from the initial
  /// pose, and its rate (rad/s or m/s); 0 for a fixed or skipped joint.
  double Position(int joint) const;
  double Rate(int joint) const;
  /// How far joint `joint` is open (m; JointGap, joint_projection.h), and how far it may be
  /// (JointBreakGap of its bodies' distance as built); 0 and infinite for a skipped joint.
  double Gap(int joint) const;
  double BreakGap(int joint) const { return break_gaps_.at(static_cast<size_t>(joint)); }
  /// Whether a joint is open beyond its BreakGap; `largest` (when given) is raised to the widest
  /// gap.
  bool AnyOpen(double* largest = nullptr) const;

  /// Joint `joint`'s ODE joint (null when skipped), and what JointRows needs of it
  /// (ode_joint_rows.h: the Newton solver's rows of a hinge or slider whose first body moves).
  dxJoint* ode_joint(int joint) const { return joints_.at(static_cast<size_t>(joint)); }
  const JointFrame& frame(int joint) const { return frames_.at(static_cast<size_t>(joint)); }
  /// The world joint whose ODE joint is `joint`, or -1.
  int IndexOf(const dxJoint* joint) const;
  /// A hinge's or slider's placement (joint_projection.h), as built (a fixed joint's: only
  /// first_is_child): with its first body the
  /// child of its second (or of the world), or with its second body the child of its first.
  const JointPlacement& placement(int joint, bool first_is_child) const {
    const Placements& both = placements_.at(static_cast<size_t>(joint));
    return first_is_child ? both.first_child : both.second_child;
  }

 private:
  struct Placements {
    JointPlacement first_child, second_child;
  };
  void Record(dxJoint* joint, const WorldJointDesc& desc);

  std::vector<dxJoint*> joints_;  ///< one per WorldJointDesc; null when skipped
  std::vector<WorldJointType> types_;
  std::vector<JointFrame> frames_;
  std::vector<Placements> placements_;
  std::vector<double> break_gaps_;  ///< m, per joint
};

}  // namespace lamina::core
