// SPDX-License-Identifier: MIT
#include "core/sim/ode_robot.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/mass_properties.h"
#include "core/robot/kinematics.h"
#include "core/sim/ode_conversions.h"

namespace lamina::core {

namespace {

// a revolute joint whose range is this wide or wider is followed through whole turns
constexpr double kFullTurn = 2 * kPi;
// a stop of a wide-range joint is given to ODE only while it lies this far inside the hinge's
// (-π, π] reading, where ODE's angle test does not wrap
constexpr double kStopWrapMargin = 0.1;
// a joint this close to a limit may be at its stop in ODE's reading (rad or m)
constexpr double kAtStopTolerance = 1e-9;
// fastest correction of a joint beyond its range (rad/s or m/s)
constexpr double kMaxStopCorrectionSpeed = 0.5;
// dry joint friction's CFM ((rad/s)/(N·m) or (m/s)/N): a sticking joint creeps 1e-9 rad/s per
// N·m it holds. Not 0: every row of the Newton solver is soft (ode_joint_rows.h), and both
// solvers then solve the same rows
constexpr double kDryFrictionCfm = 1e-9;
// ODE rejects massless bodies: a massless moving link gets this mass (kg), as in Klamp't
constexpr double kMinimumLinkMass = 1e-3;

void PlaceBody(dBodyID body, const Mat3& rotation, const Vec3& position) {
  SetBodyRotation(body, rotation);
  dBodySetPosition(body, position.x(), position.y(), position.z());
}

std::vector<JointType> LinkJointTypes(const RobotDesc& robot) {
  std::vector<JointType> types(robot.links.size(), JointType::kNormal);
  for (const JointDesc& joint : robot.joints) {
    if (joint.link < 0 || joint.link >= robot.dof()) continue;
    if (joint.type == JointType::kFloating || joint.type == JointType::kFloatingPlanar ||
        joint.type == JointType::kBallAndSocket) {
      for (int i = joint.base + 1; i <= joint.link; ++i) types[i] = joint.type;
    } else {
      types[joint.link] = joint.type;
    }
  }
  return types;
}

// true when links first..last are Klamp't's floating base: translations along x, y, z, then
// (for a 6-link base) rotations about z, y, x, each frame on its parent's
bool IsStandardFloatingBase(const RobotDesc& robot, int first, int last) {
  if (last - first != 5 && last - first != 2) return false;
  const Vec3 axes[6] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(),
                        Vec3::UnitZ(), Vec3::UnitY(), Vec3::UnitX()};
  for (int k = 0; k <= last - first; ++k) {
    const LinkDesc& link = robot.links[first + k];
    const LinkJointAxis expected = k < 3 ? LinkJointAxis::kPrismatic : LinkJointAxis::kRevolute;
    if (link.axis_type != expected || (link.axis.normalized() - axes[k]).norm() > 1e-9) {
      return false;
    }
    if (k > 0 && (link.parent != first + k - 1 ||
                  !link.parent_transform.isApprox(Pose::Identity(), 1e-12))) {
      return false;
    }
  }
  return true;
}

// every link after the links below it (a post-order of the tree)
std::vector<int> ChildrenFirst(const RobotDesc& robot) {
  const int count = static_cast<int>(robot.links.size());
  std::vector<std::vector<int>> children(count);
  std::vector<int> roots;
  for (int i = 0; i < count; ++i) {
    const int parent = robot.links[i].parent;
    (parent >= 0 && parent < count ? children[parent] : roots).push_back(i);
  }
  std::vector<int> order;
  std::vector<std::pair<int, size_t>> stack;  // a link and its next child
  for (int root : roots) {
    stack.emplace_back(root, 0);
    while (!stack.empty()) {
      const int link = stack.back().first;
      const size_t next = stack.back().second++;
      if (next < children[link].size()) {
        stack.emplace_back(children[link][next], 0);
      } else {
        order.push_back(link);
        stack.pop_back();
      }
    }
  }
  return order;
}

}  // namespace

OdeRobot::OdeRobot(dWorldID world, const RobotDesc& robot, Diagnostics& diagnostics)
    : robot_(robot),
      links_(robot.links.size()),
      joint_types_(LinkJointTypes(robot)),
      wide_(robot.links.size(), false),
      model_config_(robot.InitialConfig()) {
  joint_state_.turns.assign(robot.links.size(), 0);
  joint_state_.last_angle.assign(robot.links.size(), 0.0);
  for (const JointDesc& joint : robot.joints) {
    if (joint.type == JointType::kFloating) {
      if (floating_link_ >= 0 || !IsStandardFloatingBase(robot, joint.base + 1, joint.link)) {
        diagnostics.Error({robot.source_path, 0},
                          "robot '" + robot.name +
                              "': only one floating base of 6 virtual links (x, y, z, then "
                              "rotations about z, y, x) or 3 (x, y, z) is supported; the joint "
                              "is welded");
        for (int i = joint.base + 1; i <= joint.link; ++i) joint_types_[i] = JointType::kWeld;
        continue;
      }
      floating_first_ = joint.base + 1;
      floating_link_ = joint.link;
    } else if (joint.type == JointType::kFloatingPlanar ||
               joint.type == JointType::kBallAndSocket) {
      diagnostics.Error({robot.source_path, 0},
                        "robot '" + robot.name + "': " + JointTypeName(joint.type) +
                            " joints are not simulated yet; link " + std::to_string(joint.link) +
                            " is welded to its parent");
      for (int i = joint.base + 1; i <= joint.link; ++i) joint_types_[i] = JointType::kWeld;
    }
  }
  // hinges read ODE angles in (-π, π]: a joint whose range is narrower than a turn is built at
  // the middle of its range so that its stops never sit at the wrap (Klamp't drops stops that
  // touch ±π); wider ones are built at their configuration and count turns
  VecX build = model_config_;
  for (int i = 0; i < dof(); ++i) {
    const LinkDesc& link = robot.links[i];
    if (link.axis_type != LinkJointAxis::kRevolute) continue;
    const double range = link.q_max - link.q_min;
    if (joint_types_[i] == JointType::kNormal && std::isfinite(range) && range < kFullTurn) {
      build[i] = 0.5 * (link.q_min + link.q_max);
    } else {
      wide_[i] = true;
    }
  }
  BuildBodies(world, build, diagnostics);
  BuildJoints(world, build);
  children_first_ = ChildrenFirst(robot);
  SetConfig(robot.InitialConfig());
  SetVelocity(robot.InitialVelocity());
}

OdeRobot::~OdeRobot() {
  for (Link& link : links_) {
    if (link.joint) dJointDestroy(link.joint);
    if (link.servo) dJointDestroy(link.servo);
  }
  for (Link& link : links_) {
    if (link.owns_body) dBodyDestroy(link.body);
  }
}

// Every link's body: a floating base and each moving link get their own; welded links join
// their parent's body (or the world). Mass properties of a body are its links' exact sum.
void OdeRobot::BuildBodies(dWorldID world, const VecX& q, Diagnostics& diagnostics) {
  const std::vector<Pose> frames = LinkTransforms(robot_, q);
  const std::vector<int> owner = AssignOwners(frames);
  for (int o = 0; o < dof(); ++o) {
    if (owner[o] == o) CreateBody(world, o, owner, frames, diagnostics);
  }
  for (int k = 0; k < dof(); ++k) {
    if (owner[k] < 0 || owner[k] == k) continue;
    const Link& carrier = links_[owner[k]];
    const Pose o_from_k = frames[owner[k]].inverse() * frames[k];
    links_[k].body = carrier.body;
    links_[k].carrier = owner[k];
    links_[k].rotation_in_body = o_from_k.linear();
    links_[k].com = o_from_k.inverse() * carrier.com;
  }
}

// the link whose body carries each link (itself, a welded ancestor, or -1: virtual or static)
std::vector<int> OdeRobot::AssignOwners(const std::vector<Pose>& frames) {
  std::vector<int> owner(links_.size(), -1);
  for (int i = 0; i < dof(); ++i) {
    const LinkDesc& desc = robot_.links[i];
    Link& link = links_[i];
    const JointType type = joint_types_[i];
    if (type == JointType::kFloating && i != floating_link_) {
      link.kind = LinkKind::kVirtual;
    } else if (type == JointType::kWeld &&
               (desc.parent < 0 || links_[desc.parent].kind != LinkKind::kBody)) {
      link.kind = LinkKind::kStatic;
      link.fixed_pose = frames[i];
    } else if (type == JointType::kWeld) {
      owner[i] = owner[desc.parent];
    } else {
      owner[i] = i;
    }
  }
  return owner;
}

// the body of owner `o` with the composite mass of its group, in the owner's link frame
void OdeRobot::CreateBody(dWorldID world, int o, const std::vector<int>& owner,
                          const std::vector<Pose>& frames, Diagnostics& diagnostics) {
  std::vector<MassPart> parts;
  for (int k = 0; k < dof(); ++k) {
    if (owner[k] != o) continue;
    const LinkDesc& part = robot_.links[k];
    parts.push_back({part.mass, part.com, part.inertia, frames[o].inverse() * frames[k]});
  }
  const CompositeMass composite = CombineMass(parts);
  double mass = composite.mass;
  Mat3 inertia = composite.properties.inertia;
  const Vec3 com = composite.properties.valid ? composite.properties.com : robot_.links[o].com;
  Link& link = links_[o];
  link.body = dBodyCreate(world);
  link.owns_body = true;
  link.carrier = o;
  dBodySetFiniteRotationMode(link.body, 1);
  // a translating floating base has no rotational DOFs: its body never turns
  if (o == floating_link_ && !floating_rotates()) dBodySetMaxAngularSpeed(link.body, 0.0);
  dMass ode_mass;
  dMassSetParameters(&ode_mass, mass, 0, 0, 0, inertia(0, 0), inertia(1, 1), inertia(2, 2),
                     inertia(0, 1), inertia(0, 2), inertia(1, 2));
  if (!dMassCheck(&ode_mass)) {
    diagnostics.Note({robot_.source_path, 0},
                     "robot '" + robot_.name + "': link '" + robot_.links[o].name +
                         "' has no valid mass or inertia; simulated with 1 g");
    mass = std::max(mass, kMinimumLinkMass);
    inertia = kMinimumLinkMass * Mat3::Identity();
    dMassSetParameters(&ode_mass, mass, 0, 0, 0, inertia(0, 0), inertia(1, 1), inertia(2, 2), 0, 0,
                       0);
  }
  dBodySetMass(link.body, &ode_mass);
  link.mass = ode_mass.mass;
  link.inertia = inertia;
  link.com = com;
  PlaceBody(link.body, frames[o].linear(), frames[o] * com);
}

void OdeRobot::BuildJoints(dWorldID world, const VecX& q) {
  const std::vector<Pose> frames = LinkTransforms(robot_, q);
  for (int i = 0; i < dof(); ++i) {
    const JointType type = joint_types_[i];
    if (type != JointType::kNormal && type != JointType::kSpin) continue;
    const LinkDesc& desc = robot_.links[i];
    Link& link = links_[i];
    if (link.kind != LinkKind::kBody || !link.owns_body) continue;
    const dBodyID parent = desc.parent >= 0 ? links_[desc.parent].body : nullptr;
    const Vec3 axis = frames[i].linear() * desc.axis.normalized();
    const Vec3 origin = frames[i].translation();
    link.reference = q[i];
    if (desc.axis_type == LinkJointAxis::kRevolute) {
      link.joint = dJointCreateHinge(world, nullptr);
      dJointAttach(link.joint, link.body, parent);
      dJointSetHingeAnchor(link.joint, origin.x(), origin.y(), origin.z());
      dJointSetHingeAxis(link.joint, axis.x(), axis.y(), axis.z());
      link.frame = OdeHingeFrame(parent, axis);
      link.servo = dJointCreateAMotor(world, nullptr);
      dJointAttach(link.servo, link.body, parent);
      dJointSetAMotorMode(link.servo, dAMotorUser);
      // axis 0: the servo; axis 1: joint friction (SetJointMotor)
      dJointSetAMotorNumAxes(link.servo, 2);
      for (int k = 0; k < 2; ++k)
        dJointSetAMotorAxis(link.servo, k, 1, axis.x(), axis.y(), axis.z());
      dJointSetAMotorParam(link.servo, dParamFMax, 0.0);
      dJointSetAMotorParam(link.servo, dParamFMax2, 0.0);
    } else {
      link.joint = dJointCreateSlider(world, nullptr);
      dJointAttach(link.joint, link.body, parent);
      dJointSetSliderAxis(link.joint, axis.x(), axis.y(), axis.z());
      link.frame = OdeSliderFrame(link.body, parent, axis);
      link.servo = dJointCreateLMotor(world, nullptr);
      dJointAttach(link.servo, link.body, parent);
      dJointSetLMotorNumAxes(link.servo, 2);
      for (int k = 0; k < 2; ++k)
        dJointSetLMotorAxis(link.servo, k, 1, axis.x(), axis.y(), axis.z());
      dJointSetLMotorParam(link.servo, dParamFMax, 0.0);
      dJointSetLMotorParam(link.servo, dParamFMax2, 0.0);
    }
    SetStops(i);
  }
}

// fixed stops: sliders and hinges narrower than a turn (built at mid-range); spin joints and
// joints without limits have none; wide hinges get theirs in PrepareStep
void OdeRobot::SetStops(int i) {
  const LinkDesc& desc = robot_.links[i];
  Link& link = links_[i];
  if (joint_types_[i] == JointType::kSpin || wide_[i]) return;
  const double lo = std::isfinite(desc.q_min) ? desc.q_min - link.reference : -dInfinity;
  const double hi = std::isfinite(desc.q_max) ? desc.q_max - link.reference : dInfinity;
  if (desc.axis_type == LinkJointAxis::kRevolute) {
    dJointSetHingeParam(link.joint, dParamLoStop, lo);
    dJointSetHingeParam(link.joint, dParamHiStop, hi);
    dJointSetHingeParam(link.joint, dParamBounce, 0.0);
  } else {
    dJointSetSliderParam(link.joint, dParamLoStop, lo);
    dJointSetSliderParam(link.joint, dParamHiStop, hi);
    dJointSetSliderParam(link.joint, dParamBounce, 0.0);
  }
}

void OdeRobot::UpdateStops(int i) {
  const LinkDesc& desc = robot_.links[i];
  Link& link = links_[i];
  if (link.joint == nullptr || joint_types_[i] == JointType::kSpin) return;
  const double limit = kPi - kStopWrapMargin;
  if (!wide_[i] && desc.axis_type == LinkJointAxis::kRevolute &&
      !(desc.q_min - link.reference > -limit && desc.q_max - link.reference < limit)) {
    // ODE's reading of the hinge would wrap inside the range: from now on the stops follow
    // the angle every step (PrepareStep) and whole turns are counted (none so far)
    wide_[i] = true;
    joint_state_.turns[i] = 0;
    joint_state_.last_angle[i] = HingeAngle(i);
    dJointSetHingeParam(link.joint, dParamLoStop, -dInfinity);
    dJointSetHingeParam(link.joint, dParamHiStop, dInfinity);
    return;
  }
  SetStops(i);
}

double OdeRobot::HingeAngle(int i) const {
  return dJointGetHingeAngle(links_[i].joint);
}

void OdeRobot::PrepareStep(const VecX& q, double step, double erp) {
  for (int i = 0; i < dof(); ++i) {
    if (links_[i].joint == nullptr || joint_types_[i] == JointType::kSpin) continue;
    const LinkDesc& desc = robot_.links[i];
    if (!std::isfinite(desc.q_min) && !std::isfinite(desc.q_max)) continue;
    const bool revolute = desc.axis_type == LinkJointAxis::kRevolute;
    if (wide_[i]) {
      const double angle = HingeAngle(i);
      // the stops in ODE's reading of the hinge, when they lie inside it
      const double lo = angle + (desc.q_min - q[i]);
      const double hi = angle + (desc.q_max - q[i]);
      const double limit = kPi - kStopWrapMargin;
      dJointSetHingeParam(links_[i].joint, dParamLoStop, -dInfinity);
      dJointSetHingeParam(links_[i].joint, dParamHiStop, std::abs(hi) < limit ? hi : dInfinity);
      dJointSetHingeParam(links_[i].joint, dParamLoStop, std::abs(lo) < limit ? lo : -dInfinity);
    }
    // a joint beyond its range (its limits were just narrowed, or it starts outside them) is
    // brought back no faster than kMaxStopCorrectionSpeed: ODE's stop ERP alone would swing it
    // back at ERP·violation/h (a 0.24 rad violation: 220 rad/s in one 1 ms step)
    const double violation = std::max({desc.q_min - q[i], q[i] - desc.q_max, 0.0});
    const double stop_erp =
        violation > 0.0 ? std::min(erp, kMaxStopCorrectionSpeed * step / violation) : erp;
    if (revolute) {
      dJointSetHingeParam(links_[i].joint, dParamStopERP, stop_erp);
    } else {
      dJointSetSliderParam(links_[i].joint, dParamStopERP, stop_erp);
    }
  }
}

void OdeRobot::AcceptStep() {
  for (int i = 0; i < dof(); ++i) {
    if (!wide_[i] || links_[i].joint == nullptr) continue;
    const double angle = HingeAngle(i);
    const double jump = angle - joint_state_.last_angle[i];
    if (jump > kPi) --joint_state_.turns[i];
    if (jump < -kPi) ++joint_state_.turns[i];
    joint_state_.last_angle[i] = angle;
  }
}

void OdeRobot::CaptureJointState(RobotJointState* state) const {
  *state = joint_state_;
}

void OdeRobot::RestoreJointState(const RobotJointState& state) {
  if (state.turns.size() == joint_state_.turns.size()) joint_state_ = state;
}

// the floating base link's frame in the frame its first virtual link hangs from
Pose OdeRobot::FloatingBaseLocalFrame() const {
  const Link& base = links_[floating_link_];
  const Mat3 R = ToMat3(dBodyGetRotation(base.body));
  Pose frame = Pose::Identity();
  frame.linear() = R;
  frame.translation() = ToVec3(dBodyGetPosition(base.body)) - R * base.com;
  return robot_.links[floating_first_].parent_transform.inverse() * frame;
}

void OdeRobot::GetConfig(VecX* q) const {
  *q = model_config_;
  for (int i = 0; i < dof(); ++i) {
    const Link& link = links_[i];
    if (link.joint == nullptr) continue;
    if (robot_.links[i].axis_type == LinkJointAxis::kRevolute) {
      (*q)[i] = link.reference + HingeAngle(i) + kFullTurn * joint_state_.turns[i];
    } else {
      (*q)[i] = link.reference + dJointGetSliderPosition(link.joint);
    }
  }
  if (floating_link_ < 0) return;
  const Pose local = FloatingBaseLocalFrame();
  q->segment<3>(floating_first_) = local.translation();
  if (!floating_rotates()) return;
  const Vec3 rpy = RollPitchYawFromRotation(local.linear());
  (*q)[floating_first_ + 3] = rpy.z();
  (*q)[floating_first_ + 4] = rpy.y();
  (*q)[floating_first_ + 5] = rpy.x();
}

void OdeRobot::GetVelocity(VecX* dq) const {
  *dq = VecX::Zero(dof());
  for (int i = 0; i < dof(); ++i) {
    const Link& link = links_[i];
    if (link.joint == nullptr) continue;
    (*dq)[i] = robot_.links[i].axis_type == LinkJointAxis::kRevolute
                   ? dJointGetHingeAngleRate(link.joint)
                   : dJointGetSliderPositionRate(link.joint);
  }
  if (floating_link_ < 0) return;
  const Link& base = links_[floating_link_];
  const Mat3 R = ToMat3(dBodyGetRotation(base.body));
  const Vec3 w = ToVec3(dBodyGetAngularVel(base.body));
  const Vec3 v_origin = ToVec3(dBodyGetLinearVel(base.body)) - w.cross(R * base.com);
  const Mat3 P = robot_.links[floating_first_].parent_transform.linear();
  dq->segment<3>(floating_first_) = P.transpose() * v_origin;
  if (!floating_rotates()) return;
  // ω = yaw' z + pitch' Rz(yaw) y + roll' Rz(yaw) Ry(pitch) x, in the base's parent axes
  const Vec3 rpy = RollPitchYawFromRotation(FloatingBaseLocalFrame().linear());
  const Mat3 Rz = Eigen::AngleAxisd(rpy.z(), Vec3::UnitZ()).toRotationMatrix();
  const Mat3 Ry = Eigen::AngleAxisd(rpy.y(), Vec3::UnitY()).toRotationMatrix();
  Mat3 E;
  E.col(0) = Vec3::UnitZ();
  E.col(1) = Rz * Vec3::UnitY();
  E.col(2) = Rz * Ry * Vec3::UnitX();
  dq->segment<3>(floating_first_ + 3) =
      E.completeOrthogonalDecomposition().solve(P.transpose() * w);
}

void OdeRobot::SetConfig(const VecX& q) {
  model_config_ = q;
  const std::vector<Pose> frames = LinkTransforms(robot_, q);
  for (int i = 0; i < dof(); ++i) {
    const Link& link = links_[i];
    if (!link.owns_body) continue;
    PlaceBody(link.body, frames[i].linear(), frames[i] * link.com);
  }
  for (int i = 0; i < dof(); ++i) {
    if (!wide_[i] || links_[i].joint == nullptr) continue;
    const double angle = HingeAngle(i);
    joint_state_.turns[i] =
        static_cast<int>(std::lround((q[i] - links_[i].reference - angle) / kFullTurn));
    joint_state_.last_angle[i] = angle;
  }
}

void OdeRobot::SetVelocity(const VecX& dq) {
  VecX q;
  GetConfig(&q);
  SetLinkVelocities(LinkTransforms(robot_, q), dq, nullptr);
}

// every body's velocity for joint rates dq at link frames `frames`, parents first; with `base`
// (angular, then its origin's linear) the floating link moves so, whatever dq says of it
void OdeRobot::SetLinkVelocities(const std::vector<Pose>& frames, const VecX& dq,
                                 const Vec6* base) {
  std::vector<Vec3> w(dof(), Vec3::Zero()), v(dof(), Vec3::Zero());  // at link origins
  for (int i = 0; i < dof(); ++i) {
    const LinkDesc& desc = robot_.links[i];
    if (desc.parent >= 0) {
      w[i] = w[desc.parent];
      v[i] = v[desc.parent] +
             w[desc.parent].cross(frames[i].translation() - frames[desc.parent].translation());
    }
    if (base != nullptr && i == floating_link_) {
      w[i] = base->head<3>();
      v[i] = base->tail<3>();
      continue;
    }
    if (joint_types_[i] == JointType::kWeld) continue;
    const Vec3 axis = frames[i].linear() * desc.axis.normalized();
    if (desc.axis_type == LinkJointAxis::kRevolute) {
      w[i] += dq[i] * axis;
    } else {
      v[i] += dq[i] * axis;
    }
  }
  for (int i = 0; i < dof(); ++i) {
    const Link& link = links_[i];
    if (!link.owns_body) continue;
    const Vec3 com_velocity = v[i] + w[i].cross(frames[i].linear() * link.com);
    dBodySetLinearVel(link.body, com_velocity.x(), com_velocity.y(), com_velocity.z());
    dBodySetAngularVel(link.body, w[i].x(), w[i].y(), w[i].z());
  }
}

void OdeRobot::ProjectOntoJoints() {
  VecX q;
  GetConfig(&q);
  std::vector<Pose> frames = LinkTransforms(robot_, q);
  Vec6 base = Vec6::Zero();  // the floating link's ω and its origin's velocity
  if (floating_link_ >= 0) {
    const Link& link = links_[floating_link_];
    Pose actual = Pose::Identity();
    actual.linear() = ToMat3(dBodyGetRotation(link.body));
    actual.translation() = ToVec3(dBodyGetPosition(link.body)) - actual.linear() * link.com;
    // (q's base came through roll, pitch and yaw: the frames move onto the body as it is)
    const Pose correction = actual * frames[floating_link_].inverse();
    for (Pose& frame : frames) frame = correction * frame;
    const Vec3 w = ToVec3(dBodyGetAngularVel(link.body));
    base << w, ToVec3(dBodyGetLinearVel(link.body)) - w.cross(actual.linear() * link.com);
  }
  VecX dq;  // the joint rates as ODE reads them (the floating base's are replaced by `base`)
  GetVelocity(&dq);
  for (int i = 0; i < dof(); ++i) {
    const Link& link = links_[i];
    if (link.owns_body && i != floating_link_) {
      PlaceBody(link.body, frames[i].linear(), frames[i] * link.com);
    }
  }
  SetLinkVelocities(frames, dq, floating_link_ >= 0 ? &base : nullptr);
}

void OdeRobot::ApplyLinkForces(const VecX& forces) {
  for (int i = 0; i < dof(); ++i) {
    const double f = forces[i];
    if (f == 0.0) continue;
    const Link& link = links_[i];
    if (link.joint != nullptr) {
      if (robot_.links[i].axis_type == LinkJointAxis::kRevolute) {
        dJointAddHingeTorque(link.joint, f);
      } else {
        dJointAddSliderForce(link.joint, f);
      }
    }
  }
  if (floating_link_ < 0) return;
  // the virtual axes need the robot's kinematics: only when a driver pushes along them
  if (forces.segment(floating_first_, floating_link_ - floating_first_ + 1).isZero(0.0)) return;
  VecX q;
  GetConfig(&q);
  const std::vector<Pose> frames = LinkTransforms(robot_, q);
  const dBodyID body = links_[floating_link_].body;
  for (int i = floating_first_; i <= floating_link_; ++i) {
    const double f = forces[i];
    if (f == 0.0) continue;
    const Vec3 axis = frames[i].linear() * robot_.links[i].axis.normalized();
    if (robot_.links[i].axis_type == LinkJointAxis::kPrismatic) {
      dBodyAddForce(body, f * axis.x(), f * axis.y(), f * axis.z());
    } else {
      dBodyAddTorque(body, f * axis.x(), f * axis.y(), f * axis.z());
    }
  }
}

void OdeRobot::SetServos(const std::vector<ServoMotorCommand>& motors) {
  for (const Link& link : links_) {
    if (link.servo == nullptr) continue;
    if (dJointGetType(link.servo) == dJointTypeAMotor) {
      dJointSetAMotorParam(link.servo, dParamFMax, 0.0);
    } else {
      dJointSetLMotorParam(link.servo, dParamFMax, 0.0);
    }
  }
  for (const ServoMotorCommand& motor : motors) {
    if (motor.link < 0 || motor.link >= dof()) continue;
    const dJointID servo = links_[motor.link].servo;
    if (servo == nullptr || !(motor.fmax > 0.0)) continue;
    const double fmax = std::isfinite(motor.fmax) && !motor.unbounded ? motor.fmax : dInfinity;
    if (dJointGetType(servo) == dJointTypeAMotor) {
      dJointSetAMotorParam(servo, dParamVel, motor.velocity);
      dJointSetAMotorParam(servo, dParamCFM, motor.cfm);
      dJointSetAMotorParam(servo, dParamFMax, fmax);
    } else {
      dJointSetLMotorParam(servo, dParamVel, motor.velocity);
      dJointSetLMotorParam(servo, dParamCFM, motor.cfm);
      dJointSetLMotorParam(servo, dParamFMax, fmax);
    }
  }
}

// The joint's own motor: dry friction as a velocity-0 row bounded by μ_D (+ μ_V |dq| when the
// servo does not already damp with μ_V) of CFM kDryFrictionCfm, or pure viscous friction as an
// implicit damper (velocity 0, cfm 1 / μ_V).
void OdeRobot::SetJointFriction(const std::vector<DriverDesc>& drivers, const VecX& q,
                                const VecX& dq, const std::vector<ServoMotorCommand>& motors,
                                bool guess, const std::vector<int>& holdoff,
                                std::vector<FrictionCommand>* commands) {
  commands->clear();
  for (const DriverDesc& driver : drivers) {
    if (driver.type != DriverType::kNormal || driver.links.empty()) continue;
    const int i = driver.links[0];
    if (i < 0 || i >= dof() || links_[i].joint == nullptr) continue;
    bool viscous_in_servo = false;
    for (const ServoMotorCommand& motor : motors) {
      if (motor.link == i && motor.includes_viscous) viscous_in_servo = true;
    }
    const double dry = std::max(0.0, driver.dry_friction);
    const double viscous = viscous_in_servo ? 0.0 : std::max(0.0, driver.viscous_friction);
    double fmax = 0.0, cfm = kDryFrictionCfm;
    if (dry > 0.0) {
      fmax = dry + viscous * std::abs(dq[i]);
    } else if (viscous > 0.0) {
      fmax = dInfinity;
      cfm = 1.0 / viscous;
    }
    // at a stop ODE turns a powered joint motor into a torque of fmax into the stop (the motor
    // and the stop share one row): the infinite bound of viscous friction would blow up. The
    // motor is off while the joint sits at a stop; friction does not act for that step.
    const LinkDesc& desc = robot_.links[i];
    if (q[i] <= desc.q_min + kAtStopTolerance || q[i] >= desc.q_max - kAtStopTolerance) {
      fmax = 0.0;
    }
    FrictionCommand command{i, fmax, cfm, dq[i], FrictionRowMode::kBounded};
    const bool keep = i < static_cast<int>(holdoff.size()) && holdoff[i] > 0;
    if (guess && !keep && dry > 0.0) command.mode = ChooseFrictionRow(fmax, cfm, dq[i]);
    if (command.mode != FrictionRowMode::kBounded) commands->push_back(command);
    const double bound = command.mode == FrictionRowMode::kUnbounded  ? dInfinity
                         : command.mode == FrictionRowMode::kExplicit ? 0.0
                                                                      : fmax;
    SetJointMotor(i, bound, cfm);
  }
}

// The friction row is the second axis of the servo's motor joint, not the hinge's (or slider's)
// own motor: a hinge with a motor row is a "mixed" joint to dWorldStep, and only joints whose rows
// are all unbounded join the LCP's unbounded block, factorized at once; the rows of mixed joints
// go through Dantzig's pivoting one at a time (HRP-2 with joint friction: 150 hinge rows).
void OdeRobot::MergeHoldingFriction(const std::vector<ServoMotorCommand>& motors,
                                    const std::vector<FrictionCommand>& friction) {
  for (const FrictionCommand& row : friction) {
    if (row.mode != FrictionRowMode::kUnbounded) continue;
    const dJointID servo = links_[row.link].servo;
    for (const ServoMotorCommand& motor : motors) {
      if (motor.link != row.link || !(motor.fmax > 0.0)) continue;
      if (!motor.unbounded && std::isfinite(motor.fmax)) continue;
      if (!(motor.cfm + row.cfm > 0.0)) continue;
      const MergedRow merged = MergeServoAndFrictionRows(motor.velocity, motor.cfm, row.cfm);
      if (dJointGetType(servo) == dJointTypeAMotor) {
        dJointSetAMotorParam(servo, dParamVel, merged.velocity);
        dJointSetAMotorParam(servo, dParamCFM, merged.cfm);
        dJointSetAMotorParam(servo, dParamFMax2, 0.0);
      } else {
        dJointSetLMotorParam(servo, dParamVel, merged.velocity);
        dJointSetLMotorParam(servo, dParamCFM, merged.cfm);
        dJointSetLMotorParam(servo, dParamFMax2, 0.0);
      }
    }
  }
}

void OdeRobot::SetJointMotor(int i, double fmax, double cfm) {
  const dJointID motor = links_[i].servo;
  if (motor == nullptr) return;
  if (dJointGetType(motor) == dJointTypeAMotor) {
    dJointSetAMotorParam(motor, dParamVel2, 0.0);
    dJointSetAMotorParam(motor, dParamCFM2, cfm);
    dJointSetAMotorParam(motor, dParamFMax2, fmax);
  } else {
    dJointSetLMotorParam(motor, dParamVel2, 0.0);
    dJointSetLMotorParam(motor, dParamCFM2, cfm);
    dJointSetLMotorParam(motor, dParamFMax2, fmax);
  }
}

}  // namespace lamina::core
