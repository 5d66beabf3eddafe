// SPDX-License-Identifier: MIT
#include "core/sim/joint_stabilization.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

namespace {

using Column = ProfileCholesky::Column;

// the directions, in the parent's axes, along which a joint's gap is counted: all three for a
// hinge's point or a fixed joint's, the two across a slider's axis
int GapDirections(const JointPlacement& joint, Vec3 directions[3]) {
  if (!joint.slider || joint.axis.isZero(0.0)) {
    for (int k = 0; k < 3; ++k) directions[k] = Vec3::Unit(k);
    return 3;
  }
  directions[0] = joint.axis.unitOrthogonal();
  directions[1] = joint.axis.cross(directions[0]).normalized();
  return 2;
}

Column RowOf(const Vec3& linear, const Vec3& angular) {
  Column column;
  column.head<3>() = linear;
  column.tail<3>() = angular;
  return column;
}

// the child's point of the joint in the world: a hinge's axis point, a slider's or fixed
// joint's centre of mass
Vec3 CarriedChildPoint(const JointPlacement& joint, const BodyState& child) {
  if (joint.slider) return child.com_position;
  return child.com_position + child.orientation * joint.child_point;
}

// the rotation by the world vector `turn` (rad) applied to `orientation`
Eigen::Quaterniond Turned(const Eigen::Quaterniond& orientation, const Vec3& turn) {
  const double angle = turn.norm();
  if (angle == 0.0) return orientation;
  return (Eigen::Quaterniond(Eigen::AngleAxisd(angle, turn / angle)) * orientation).normalized();
}

const BodyState& ParentOf(const std::vector<StabilizedBody>& bodies, const StabilizedJoint& joint,
                          bool start) {
  static const BodyState kWorld;
  if (joint.parent < 0) return kWorld;
  const StabilizedBody& parent = bodies[static_cast<size_t>(joint.parent)];
  return start ? parent.start : parent.state;
}

}  // namespace

Vec3 ArcOffset(const Vec3& arm, const Vec3& angular_velocity, double step, Vec3* velocity_change) {
  const Vec3 turn = step * angular_velocity;
  const double angle = turn.norm();
  if (angle == 0.0) {
    velocity_change->setZero();
    return Vec3::Zero();
  }
  const Vec3 turned = Eigen::AngleAxisd(angle, turn / angle) * arm - arm;
  *velocity_change = angular_velocity.cross(turned);
  return turned - turn.cross(arm);
}

// each moving body on a hinge to the world carried along its arc (ArcOffset), once (a second
// world hinge of the same body shares its axis, or holds it still)
void JointStabilizer::FollowWorldHinges(std::vector<StabilizedBody>* bodies,
                                        const std::vector<StabilizedJoint>& joints, double step) {
  followed_.assign(bodies->size(), 0);
  for (const StabilizedJoint& joint : joints) {
    const JointPlacement& placement = joint.placement;
    const size_t child = static_cast<size_t>(joint.child);
    if (joint.parent >= 0 || placement.slider || !(*bodies)[child].moves || followed_[child])
      continue;
    followed_[child] = 1;
    StabilizedBody& body = (*bodies)[child];
    const Vec3 arm = -(body.start.orientation * placement.child_point);
    Vec3 velocity_change;
    body.state.com_position += ArcOffset(arm, body.state.angular_velocity, step, &velocity_change);
    body.state.linear_velocity += velocity_change;
  }
}

JointStabilizer::Result JointStabilizer::Stabilize(std::vector<StabilizedBody>* bodies,
                                                   const std::vector<StabilizedJoint>& joints,
                                                   double step, double erp, double tolerance) {
  Result result;
  FollowWorldHinges(bodies, joints, step);
  // the gaps the step's rows aimed at: what the ERP leaves of the gaps at the start
  intended_.resize(joints.size());
  for (size_t j = 0; j < joints.size(); ++j) {
    const StabilizedJoint& joint = joints[j];
    intended_[j] = (1.0 - erp) * JointGapVector(joint.placement, ParentOf(*bodies, joint, true),
                                                (*bodies)[static_cast<size_t>(joint.child)].start);
  }
  double widest = MeasureGaps(*bodies, joints);
  result.gap_before = widest;
  result.gap_after = widest;
  if (!(widest > tolerance)) return result;  // (a gap that is not finite is left to the guard)
  BuildRows(*bodies, joints);
  Profile(*bodies, joints);
  if (!Factor(*bodies, joints)) return result;
  const double enough = std::max(tolerance, kReduction * widest);
  kept_.clear();
  for (const StabilizedBody& body : *bodies) kept_.push_back(body.state);
  moved_.setZero(step_.size());
  double last = widest;
  while (widest > enough && result.rounds < kMaxRounds) {
    SolveRound(bodies, joints);
    ++result.rounds;
    widest = MeasureGaps(*bodies, joints);
    // a round that leaves more than kSlowRound of the drift: the rows of the start do not reach
    // it (they turned too far in the step, or they are near a singular pose)
    if (!(widest <= kSlowRound * last)) break;
    last = widest;
  }
  if (!(widest <= enough)) {  // not closed: the step's poses as they were
    for (size_t b = 0; b < bodies->size(); ++b) (*bodies)[b].state = kept_[b];
    return result;
  }
  result.gap_after = widest;
  result.applied = true;
  // the velocity that would have carried the bodies there over the step
  for (size_t b = 0; b < bodies->size(); ++b) {
    if (block_[b] < 0) continue;
    BodyState& state = (*bodies)[b].state;
    state.linear_velocity += moved_.segment<3>(6 * block_[b]) / step;
    state.angular_velocity += moved_.segment<3>(6 * block_[b] + 3) / step;
  }
  return result;
}

// each joint's drift at the current poses (its gap vector less the one the step aimed at), in the
// directions its rows take at the start; returns the widest (m)
double JointStabilizer::MeasureGaps(const std::vector<StabilizedBody>& bodies,
                                    const std::vector<StabilizedJoint>& joints) {
  gaps_.resize(joints.size());
  double widest = 0.0;
  for (size_t j = 0; j < joints.size(); ++j) {
    const StabilizedJoint& joint = joints[j];
    const Vec3 gap = JointGapVector(joint.placement, ParentOf(bodies, joint, false),
                                    bodies[static_cast<size_t>(joint.child)].state) -
                     intended_[j];
    widest = std::max(widest, gap.norm());
    Vec3 directions[3];
    const int count = GapDirections(joint.placement, directions);
    const Eigen::Quaterniond& turn = ParentOf(bodies, joint, true).orientation;
    gaps_[j].setZero();
    for (int k = 0; k < count; ++k) gaps_[j](k) = (turn * directions[k]).dot(gap);
  }
  return widest;
}

void JointStabilizer::BuildRows(const std::vector<StabilizedBody>& bodies,
                                const std::vector<StabilizedJoint>& joints) {
  rows_.clear();
  for (size_t j = 0; j < joints.size(); ++j) {
    const StabilizedJoint& joint = joints[j];
    AddJointRows(static_cast<int>(j), joint.placement, ParentOf(bodies, joint, true),
                 bodies[static_cast<size_t>(joint.child)].start);
  }
}

// J₀ of a joint's rows at the start: a gap row along the parent-carried direction e has
// J_child = (e, r_c × e) and J_parent = −(e, (p_c − x_p) × e) (e turns with the parent); a
// rotation row about u has (0, u) and (0, −u)
void JointStabilizer::AddJointRows(int joint, const JointPlacement& placement,
                                   const BodyState& parent, const BodyState& child) {
  const Vec3 child_point = CarriedChildPoint(placement, child);
  const Vec3 child_arm = child_point - child.com_position;
  const Vec3 parent_arm = child_point - parent.com_position;
  Vec3 directions[3];
  const int count = GapDirections(placement, directions);
  for (int k = 0; k < count; ++k) {
    const Vec3 e = parent.orientation * directions[k];
    rows_.push_back({joint, k, -RowOf(e, parent_arm.cross(e)), RowOf(e, child_arm.cross(e))});
  }
  // the rotation rows: about the two directions across a hinge's axis, all three otherwise
  Vec3 turns[3] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  int turn_count = 3;
  if (!placement.slider) {
    const Vec3 axis = parent.orientation * placement.axis;
    turns[0] = axis.unitOrthogonal();
    turns[1] = axis.cross(turns[0]).normalized();
    turn_count = 2;
  }
  for (int k = 0; k < turn_count; ++k) {
    rows_.push_back({joint, -1, RowOf(Vec3::Zero(), -turns[k]), RowOf(Vec3::Zero(), turns[k])});
  }
}

// blocks for the bodies that move, in their order; a joint between two of them reaches from the
// later one's block row back to the earlier one's
void JointStabilizer::Profile(const std::vector<StabilizedBody>& bodies,
                              const std::vector<StabilizedJoint>& joints) {
  block_.assign(bodies.size(), -1);
  first_.clear();
  for (size_t b = 0; b < bodies.size(); ++b) {
    if (!bodies[b].moves) continue;
    block_[b] = static_cast<int>(first_.size());
    first_.push_back(block_[b]);
  }
  for (const StabilizedJoint& joint : joints) {
    const int a = joint.parent < 0 ? -1 : block_[static_cast<size_t>(joint.parent)];
    const int b = block_[static_cast<size_t>(joint.child)];
    if (a < 0 || b < 0) continue;
    int& first = first_[static_cast<size_t>(std::max(a, b))];
    first = std::min(first, std::min(a, b));
  }
}

// M + w·J₀ᵀJ₀ (M with the inertia turned as at the start), factored
bool JointStabilizer::Factor(const std::vector<StabilizedBody>& bodies,
                             const std::vector<StabilizedJoint>& joints) {
  matrix_.Reset(first_);
  step_.setZero(6 * static_cast<Eigen::Index>(first_.size()));
  double heaviest = 0.0;
  for (size_t b = 0; b < bodies.size(); ++b) {
    if (block_[b] < 0) continue;
    const StabilizedBody& body = bodies[b];
    heaviest = std::max(heaviest, body.mass);
    const Mat3 rotation = body.start.orientation.toRotationMatrix();
    ProfileCholesky::Block& diagonal = matrix_.block(block_[b], block_[b]);
    diagonal.topLeftCorner<3, 3>() = body.mass * Mat3::Identity();
    diagonal.bottomRightCorner<3, 3>() = rotation * body.inertia * rotation.transpose();
  }
  w_ = kPenalty * heaviest;
  for (const Row& row : rows_) {
    const StabilizedJoint& joint = joints[static_cast<size_t>(row.joint)];
    const int c = block_[static_cast<size_t>(joint.child)];
    const int p = joint.parent < 0 ? -1 : block_[static_cast<size_t>(joint.parent)];
    if (c >= 0) AddRowBlocks(c, row.child);
    if (p >= 0) AddRowBlocks(p, row.parent);
    if (c < 0 || p < 0) continue;
    const bool child_later = c > p;
    ProfileCholesky::AddOuter(w_ * (child_later ? row.child : row.parent),
                              child_later ? row.parent : row.child,
                              &matrix_.block(std::max(c, p), std::min(c, p)));
  }
  return matrix_.Factor();
}

void JointStabilizer::AddRowBlocks(int block, const ProfileCholesky::Column& jacobian) {
  ProfileCholesky::AddLowerOuter(w_ * jacobian, jacobian, &matrix_.block(block, block));
}

// one round: Δq = −(M + w·J₀ᵀJ₀)⁻¹ w·J₀ᵀc, every moving body moved by its Δq
void JointStabilizer::SolveRound(std::vector<StabilizedBody>* bodies,
                                 const std::vector<StabilizedJoint>& joints) {
  step_.setZero();
  for (const Row& row : rows_) {
    if (row.gap < 0) continue;
    const double gap = gaps_[static_cast<size_t>(row.joint)](row.gap);
    const StabilizedJoint& joint = joints[static_cast<size_t>(row.joint)];
    const int c = block_[static_cast<size_t>(joint.child)];
    const int p = joint.parent < 0 ? -1 : block_[static_cast<size_t>(joint.parent)];
    if (c >= 0) step_.segment<6>(6 * c) -= w_ * gap * row.child;
    if (p >= 0) step_.segment<6>(6 * p) -= w_ * gap * row.parent;
  }
  matrix_.Solve(&step_);
  moved_ += step_;
  for (size_t b = 0; b < bodies->size(); ++b) {
    if (block_[b] < 0) continue;
    BodyState& state = (*bodies)[b].state;
    state.com_position += step_.segment<3>(6 * block_[b]);
    state.orientation = Turned(state.orientation, step_.segment<3>(6 * block_[b] + 3));
  }
}

}  // namespace lamina::core
