// SPDX-License-Identifier: MIT
// Robot links in the step guard (step_guard.h covers rigid objects). A robot's links are ODE
// bodies held together by ODE joints, so a robot blows up differently from a free body: a step
// that drives a link absurdly fast (1e12 N·m commanded on a joint with no torque limit, a huge
// applied wrench) moves its bodies along the velocities ODE solved for, and the joints, which ODE
// holds at the velocity level and corrects only by ERP afterwards, come apart — by 5e8 m in one
// 1 ms step for that torque on a 0.1 kg link. Without this check such a run went on silently
// (status "normal", links 4e8 m away after 0.1 s). From about 1e155 N·m ODE fails inside its
// step (a quaternion it cannot normalize), which still stops the run with an error.
//
// The rules:
//   - A joint's gap is its link's frame origin's distance from where its parent's frame and its
//     parent_transform put it. A prismatic joint's travel along its axis does not count while it
//     is within the joint's limits; beyond them it does (the stop is open).
//   - A step that opened a joint of a robot by more than max(1 cm, 10 % of the link's offset
//     from its parent) (JointBreakGap) beyond what it was at the start of the step has broken the
//     robot: the robot is put back where it was at the start of the step, at rest (every link
//     stopped), and the step is flagged corrected (status "unstable"). Its other bodies keep their
//     step.
//   - A step after which a joint's gap exceeds JointBreakGap, however slowly it opened, is flagged
//     "joint open" (step_observer.h); nothing is corrected (there is no state to go back to), so
//     the run goes on and says so at every such step. The world's joints are watched the same way
//     (joint_projection.h's JointGap).
//   - A step that left a robot link non-finite is undone (as for objects) with every link of that
//     robot stopped, and retaken once (flagged recovered).
// So a robot given an absurd input stays where it was, finite, with every step saying so, for as
// long as the input lasts; a robot moving within what a step can follow never opens a joint that
// far in one step (the 40-link chain of worlds/stress/chain_robot.xml whipping at 1 ms opens at
// most 0.75 mm in a whole run). A torque-limited PD servo too stiff for QuickStep's explicit law
// at the step (worlds/accuracy/gripper_pad.xml at 10 ms with a limit: servoD·h/m = 5,
// explicit_pd.h) swings its slider through its stops; the stop's gap flags it.
//
// Differences from Klamp't: Klamp't has no check on a robot's joints; an energy check cannot tell
// an absurd input from a real one (the input supplies the energy, and the work bound allows it).
// The energy of robot links is not part of Lamina's energy check either: the work of the
// actuators (explicit efforts and ODE joint motors) is not observable per body, so an allowance
// would be a guess.
#pragma once

#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// The gap of every joint of `robot` given its link frames in the world (m; one per link). Links
/// whose frame or whose parent's frame is not `known` (a floating base's virtual links) have gap
/// 0; roots are measured against the world (their parent_transform).
void RobotJointGaps(const RobotDesc& robot, const std::vector<Pose>& frames,
                    const std::vector<char>& known, std::vector<double>* gaps);

/// How far a joint may open in one step before the robot counts as broken (m): max(1 cm, 10 % of
/// the link's offset from its parent).
double JointBreakGap(const LinkDesc& link);

/// True when some joint of `robot` opened from `before` to `after` by more than JointBreakGap.
bool RobotJointsBroke(const RobotDesc& robot, const std::vector<double>& before,
                      const std::vector<double>& after);

/// True when some joint of `robot` is open by more than JointBreakGap at `gaps`; `largest` (when
/// given) is raised to the largest gap.
bool RobotJointsOpen(const RobotDesc& robot, const std::vector<double>& gaps,
                     double* largest = nullptr);

}  // namespace lamina::core
