// SPDX-License-Identifier: MIT
#include "core/sim/object_islands.h"

#include <algorithm>
#include <numeric>
#include <string>

#include <ode/ode.h>

#include "core/sim/direct_solver.h"
#include "core/sim/free_body_step.h"
#include "core/sim/newton_solver.h"
#include "core/sim/ode_contact_rows.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/ode_joint_rows.h"
#include "core/sim/reduced_basis.h"
#include "core/sim/row_relaxation.h"

namespace lamina::core {

struct ObjectIslands::Kept {
  dContact contact;
  int a, b;  ///< world ids of the free bodies, -1: none
  dBodyID body_a, body_b;
  dJointFeedback* feedback;
};

struct ObjectIslands::KeptJoint {
  dJointID joint;
  int a, b;  ///< world ids of the first and second body, -1: the world
  dBodyID body_a, body_b;
  JointFrame frame;
};

// one island's solve; the vectors keep their storage from island to island
struct ObjectIslands::Island {
  std::vector<int> ids;  ///< island index -> world id
  std::vector<dBodyID> odes;
  std::vector<NewtonBody> bodies;
  std::vector<NewtonRow> rows;
  std::vector<size_t> first_row;  ///< per member, its first row (and one past the last)
  // the step's grouping of the kept contacts and joints by island
  std::vector<size_t> order;
  std::vector<int> root;
  std::vector<size_t> members;        ///< this island's kept contacts
  std::vector<size_t> joint_members;  ///< its kept joints
  NewtonSolver solver;
  DirectSolver direct;
  // the reduced step (SolveReduced): its hinges and sliders (and their joints), per body its
  // link to its parent and the edge that makes it a child (OrientTree), its centre, the basis
  std::vector<TreeEdge> edges;
  std::vector<dJointID> edge_joints;
  std::vector<TreeLink> tree;
  std::vector<int> child_edge;
  std::vector<Vec3> centres;
  ReducedBasis basis;
  NewtonResult result;
  bool newton_tried = false;  ///< this island's solve began with Newton steps

  void Clear();
  void AddBody(int id, dBodyID body, dWorldID world, double step);
  void AddWrench(size_t k, double step) const;
  /// for the kept contacts `members` (this island's)
  void ReportFeedback(const std::vector<Kept>& kept) const;
};

ObjectIslands::ObjectIslands() : island_(std::make_unique<Island>()) {}
ObjectIslands::~ObjectIslands() = default;

// ---- islands ------------------------------------------------------------------------------

void ObjectIslands::Begin(int count, bool exact, int direct_bodies, int newton_contacts) {
  exact_ = exact;
  direct_bodies_ = direct_bodies;
  newton_contacts_ = newton_contacts;
  parent_.resize(count);
  std::iota(parent_.begin(), parent_.end(), 0);
  ode_.assign(count, 0);
  local_.assign(count, -1);
  kept_.clear();
  joints_.clear();
  reduced_joints_.clear();
  reduced_tree_.clear();
}

int ObjectIslands::Root(int id) {
  while (parent_[id] != id) id = parent_[id] = parent_[parent_[id]];
  return id;
}

void ObjectIslands::Link(int a, int b) {
  const int ra = Root(a), rb = Root(b);
  if (ra == rb) return;
  parent_[rb] = ra;
  ode_[ra] = ode_[ra] || ode_[rb];
}

void ObjectIslands::Keep(const dContact& contact, int a, int b, dBodyID body_a, dBodyID body_b,
                         dJointFeedback* feedback) {
  kept_.push_back({contact, a, b, body_a, body_b, feedback});
}

void ObjectIslands::KeepJoint(dJointID joint, int a, int b, const JointFrame& frame) {
  joints_.push_back({joint, a, b, dJointGetBody(joint, 0), dJointGetBody(joint, 1), frame});
  if (b >= 0) Link(a, b);
}

int ObjectIslands::IslandOf(size_t item) {
  if (item >= kept_.size()) return Root(joints_[item - kept_.size()].a);
  const Kept& kept = kept_[item];
  return Root(kept.a >= 0 ? kept.a : kept.b);
}

void ObjectIslands::Solve(dWorldID world, dJointGroupID group, double step) {
  const size_t items = kept_.size() + joints_.size();
  if (items == 0) return;
  // (the island's scratch keeps its storage: nothing is allocated once it has grown)
  std::vector<size_t>& order = island_->order;
  std::vector<int>& root = island_->root;
  order.resize(items);
  std::iota(order.begin(), order.end(), 0);
  root.resize(items);
  for (size_t k = 0; k < items; ++k) root[k] = IslandOf(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t x, size_t y) { return root[x] < root[y]; });
  std::vector<size_t>& members = island_->members;
  std::vector<size_t>& joint_members = island_->joint_members;
  members.clear();
  joint_members.clear();
  for (size_t k = 0; k < order.size(); ++k) {
    if (order[k] < kept_.size()) {
      members.push_back(order[k]);
    } else {
      joint_members.push_back(order[k] - kept_.size());
    }
    if (k + 1 == order.size() || root[order[k + 1]] != root[order[k]]) {
      // (an island a later link made ODE's has no kept contact: its joints stay in ODE)
      if (!ode_[root[order[k]]]) SolveIsland(world, group, step);
      members.clear();
      joint_members.clear();
    }
  }
}

void ObjectIslands::Restore() {
  for (dJointID joint : disabled_) dJointEnable(joint);
  disabled_.clear();
  for (const SetAsideBody& aside : set_aside_) dBodyEnable(aside.body);  // (a failed step)
  set_aside_.clear();
}

void ObjectIslands::Island::Clear() {
  ids.clear();
  odes.clear();
  bodies.clear();
  rows.clear();
  first_row.clear();
  edges.clear();
  edge_joints.clear();
  tree.clear();
  centres.clear();
}

// a free body of the island: its mass, world inertia and the velocity ODE's step would give it
// without the rows (applied forces, gravity, the implicit gyroscopic torque: free_body_step.h)
void ObjectIslands::Island::AddBody(int id, dBodyID body, dWorldID world, double step) {
  ids.push_back(id);
  odes.push_back(body);
  dMass mass;
  dBodyGetMass(body, &mass);
  const Mat3 rotation = ToMat3(dBodyGetRotation(body));
  NewtonBody b;
  b.mass = mass.mass;
  b.inertia = rotation * ToMat3(mass.I) * rotation.transpose();
  b.start.head<3>() = ToVec3(dBodyGetLinearVel(body));
  b.start.tail<3>() = ToVec3(dBodyGetAngularVel(body));
  Vec3 force = ToVec3(dBodyGetForce(body));
  if (dBodyGetGravityMode(body) != 0) {
    dVector3 gravity;
    dWorldGetGravity(world, gravity);
    force += b.mass * ToVec3(gravity);
  }
  b.free_velocity.head<3>() = b.start.head<3>() + step * force / b.mass;
  b.free_velocity.tail<3>() =
      FreeAngularVelocity(b.inertia, b.start.tail<3>(), ToVec3(dBodyGetTorque(body)), step,
                          dBodyGetGyroscopicMode(body) != 0);
  bodies.push_back(b);
  centres.push_back(ToVec3(dBodyGetPosition(body)));
}

void ObjectIslands::SolveIsland(dWorldID world, dJointGroupID group, double step) {
  Island& island = *island_;
  const bool robot = !island.joint_members.empty();
  if (exact_ && !robot && island.members.size() < static_cast<size_t>(newton_contacts_)) {
    HandBack(world, group);  // few rows: dWorldStep's own LCP is the cheaper exact answer
    return;
  }
  ++statistics_.islands;
  if (reduced_ && robot && !exact_ && SolveReduced(world, step)) {
    Finish(step, true);
    return;
  }
  const bool built = BuildIsland(world, step, false);
  const bool large_robot =
      direct_bodies_ > 0 && robot && static_cast<int>(island.bodies.size()) >= direct_bodies_;
  // (every robot the exact solver keeps is a large one: Simulator::PrepareObjectIslands)
  island.newton_tried = false;
  const bool converged =
      built && (large_robot ? SolveLargeRobot(step) : SolveNewton(NewtonBudget(), step));
  if (!converged && built && !large_robot && island.rows.size() > kMostHandBackRows) {
    // too many rows for dWorldStep: Gauss–Seidel sweeps (row_relaxation.h)
    ++statistics_.unconverged;
    RelaxRows(island.bodies, island.rows, step, kRelaxSweeps, &island.result);
    Finish(step, false);
    return;
  }
  if (!converged) {
    ++statistics_.fallbacks;
    statistics_.newton_fallbacks += island.newton_tried;
    HandBack(world, group);
    return;
  }
  Finish(step, false);
}

// the solved island's bodies set aside for StepSetAside (or, where ODE must integrate one, its
// constraint wrench into its accumulators); its robot joints off for ODE's step (Restore enables
// them again), and after a reduced step remembered for SolvedReduced
void ObjectIslands::Finish(double step, bool reduced) {
  Island& island = *island_;
  for (size_t j : island.joint_members) {
    dJointDisable(joints_[j].joint);
    disabled_.push_back(joints_[j].joint);
    if (reduced) reduced_joints_.push_back(joints_[j].joint);
  }
  island.ReportFeedback(kept_);
  for (size_t k = 0; k < island.bodies.size(); ++k) {
    if (StepsItself(island.odes[k])) {
      set_aside_.push_back({island.odes[k], island.result.velocity[k]});
    } else {
      island.AddWrench(k, step);
    }
  }
  if (!reduced) return;
  for (int k : island.basis.order()) {
    const int e = island.child_edge[k];
    if (e >= 0) reduced_tree_.push_back({island.edge_joints[e], island.edges[e].first == k});
  }
}

// a body integrated here rather than by ODE: in finite rotation mode about no axis, undamped
// (what free_body_step.h replicates), enabled and held by no enabled ODE joint (ODE's step
// would enable it through one, and step it)
bool ObjectIslands::StepsItself(dBodyID body) {
  dVector3 axis;
  dBodyGetFiniteRotationAxis(body, axis);
  if (dBodyGetFiniteRotationMode(body) == 0 || axis[0] != 0.0 || axis[1] != 0.0 || axis[2] != 0.0 ||
      dBodyGetLinearDamping(body) != 0.0 || dBodyGetAngularDamping(body) != 0.0 ||
      dBodyIsEnabled(body) == 0) {
    return false;
  }
  for (int j = 0; j < dBodyGetNumJoints(body); ++j) {
    if (dJointIsEnabled(dBodyGetJoint(body, j)) != 0) return false;
  }
  return true;
}

void ObjectIslands::SetAside() {
  for (const SetAsideBody& aside : set_aside_) dBodyDisable(aside.body);
}

void ObjectIslands::StepSetAside(double step) {
  for (const SetAsideBody& aside : set_aside_) {
    dBodyID body = aside.body;
    const dReal* q = dBodyGetQuaternion(body);
    const FreeBodyPose pose = StepFreeBody(ToVec3(dBodyGetPosition(body)), {q[0], q[1], q[2], q[3]},
                                           aside.velocity.head<3>(), aside.velocity.tail<3>(),
                                           dBodyGetMaxAngularSpeed(body), step);
    dBodySetPosition(body, pose.position.x(), pose.position.y(), pose.position.z());
    const dQuaternion rotation = {pose.rotation[0], pose.rotation[1], pose.rotation[2],
                                  pose.rotation[3]};
    dBodySetQuaternion(body, rotation);
    dBodySetLinearVel(body, aside.velocity[0], aside.velocity[1], aside.velocity[2]);
    dBodySetAngularVel(body, pose.omega.x(), pose.omega.y(), pose.omega.z());
    dBodySetForce(body, 0.0, 0.0, 0.0);  // (as ODE's step leaves its bodies)
    dBodySetTorque(body, 0.0, 0.0, 0.0);
    dBodyEnable(body);
  }
  set_aside_.clear();
}

// the robot island in its generalized velocities (reduced_basis.h): a few Newton steps, then the
// direct solve (both cheap here: no joint rows, one unknown per joint), with the large robots'
// backoff (SolveLargeRobot); false when its joints do not form a tree or neither settles it (the
// caller takes the island over every body)
bool ObjectIslands::SolveReduced(dWorldID world, double step) {
  Island& island = *island_;
  std::string why;
  if (!BuildIsland(world, step, true) || !island.basis.Build(island.centres, island.tree, &why)) {
    return false;
  }
  ++statistics_.reduced_islands;
  RobotBackoff& backoff = BackoffOf(joints_[island.joint_members.front()].joint);
  bool converged = false;
  if (NewtonDue(&backoff)) {
    ++statistics_.newton_islands;
    NewtonOptions options;
    options.max_iterations = kReducedNewtonSteps;
    options.undamped_rounds = kUndampedReducedRounds;
    converged = island.solver.SolveReduced(island.bodies, island.rows, island.basis, step, options,
                                           &island.result);
    statistics_.iterations += island.result.iterations;
    statistics_.factorizations += island.result.factorizations;
    RecordNewton(&backoff, converged);
  }
  if (!converged) {
    ++statistics_.direct_islands;
    converged = island.direct.SolveReduced(island.bodies, island.rows, island.basis, step, {},
                                           &island.result);
    if (!converged) ++statistics_.direct_fallbacks;
  }
  if (!converged) ++statistics_.reduced_fallbacks;
  return converged;
}

bool ObjectIslands::SolvedReduced(const dxJoint* joint) const {
  return std::find(reduced_joints_.begin(), reduced_joints_.end(), joint) != reduced_joints_.end();
}

// A large robot's island: kNewtonStepsBeforeDirect Newton steps (kNewtonStepsWhileSettling
// after a Newton solve that settled), then the direct solve, unless its last Newton steps failed
// (kMostDirectSteps)
bool ObjectIslands::SolveLargeRobot(double step) {
  RobotBackoff& backoff = BackoffOf(joints_[island_->joint_members.front()].joint);
  if (robot_newton_ && NewtonDue(&backoff)) {
    const int steps = backoff.failures < kFailuresBeforeOneNewtonStep ? kNewtonStepsWhileSettling
                                                                      : kNewtonStepsBeforeDirect;
    const bool settled = SolveNewton(steps, step);
    RecordNewton(&backoff, settled);
    if (settled) return true;
  }
  return SolveDirectly(step);
}

// whether a robot's Newton steps are to be tried this step (not while its backoff runs)
bool ObjectIslands::NewtonDue(RobotBackoff* backoff) {
  if (backoff->direct_steps == 0) return true;
  --backoff->direct_steps;
  return false;
}

// after n failed Newton solves in a row, the next min(2ⁿ⁻¹, kMostDirectSteps) steps go straight
// to the direct solve
void ObjectIslands::RecordNewton(RobotBackoff* backoff, bool settled) {
  if (settled) {
    backoff->failures = 0;
    return;
  }
  backoff->direct_steps = std::min(1 << std::min(backoff->failures, 4), kMostDirectSteps);
  ++backoff->failures;
}

ObjectIslands::RobotBackoff& ObjectIslands::BackoffOf(const dxJoint* robot) {
  for (RobotBackoff& backoff : backoff_) {
    if (backoff.robot == robot) return backoff;
  }
  backoff_.push_back({robot, 0, 0});
  return backoff_.back();
}

bool ObjectIslands::SolveDirectly(double step) {
  Island& island = *island_;
  ++statistics_.direct_islands;
  const bool settled = island.direct.Solve(island.bodies, island.rows, step, {}, &island.result);
  if (!settled) ++statistics_.direct_fallbacks;
  return settled;
}

// The Newton solver's island, with at most `max_iterations` Newton steps (0: the solver's own
// budget); a large robot's gets one or two (SolveLargeRobot, which goes on to the direct solve, and
// dWorldStep when that does not settle: the Newton solver's whole budget then seldom did either,
// ATHLETE on fractal terrain 197 of 198). Where few rows change their law (a humanoid standing on a
// plane) one Newton step is the cheapest answer, where many do (feet and wheels on rough ground: 20
// Newton steps and more) one direct solve is (the robot benchmarks of docs/simulator.md).
bool ObjectIslands::SolveNewton(int max_iterations, double step) {
  Island& island = *island_;
  ++statistics_.newton_islands;
  island.newton_tried = true;
  NewtonOptions options;
  if (max_iterations > 0) options.max_iterations = max_iterations;
  // (a robot's island gets one or two Newton steps: no chord steps there)
  if (island.joint_members.empty()) options.island = IslandKey(island.ids);
  const bool converged =
      island.solver.Solve(island.bodies, island.rows, step, options, &island.result);
  statistics_.iterations += island.result.iterations;
  statistics_.factorizations += island.result.factorizations;
  return converged;
}

// the island's bodies (world ids, in order) as a key for the Newton solver's kept factorization
// (newton_solver.h): FNV-1a, never 0
unsigned long long ObjectIslands::IslandKey(const std::vector<int>& ids) {
  unsigned long long key = 14695981039346656037ull;
  for (int id : ids) key = (key ^ static_cast<unsigned>(id)) * 1099511628211ull;
  return key == 0 ? 1 : key;
}

// The Newton steps an island gets (not a large robot's: SolveLargeRobot): the solver's own budget
// (0), and for an island too large to hand back (kMostHandBackRows) one more for every four bodies,
// since the other answer is an unconverged one. A pile's transient needs them: a pyramid of 1,275
// boxes (base 50, 30,000 rows) took 8, 114, 50 and 6 Newton steps in its first four steps, then one
// a step.
int ObjectIslands::NewtonBudget() const {
  if (newton_budget_ > 0) return newton_budget_;
  const Island& island = *island_;
  if (island.rows.size() <= kMostHandBackRows) return 0;
  return NewtonOptions().max_iterations + static_cast<int>(island.bodies.size()) / 4;
}

// the island's bodies (a robot's children first, then its parents: the order the joints were
// kept in, for a narrow profile; then the contacts' bodies) and rows; false when a joint is not
// one ode_joint_rows.h replicates. `reduced`: for the reduced step, without the rows that hold a
// hinge or slider together, which set the island's tree instead
bool ObjectIslands::BuildIsland(dWorldID world, double step, bool reduced) {
  Island& island = *island_;
  island.Clear();
  auto add = [&](int id, dBodyID body) {
    if (id < 0 || local_[id] >= 0) return;
    local_[id] = static_cast<int>(island.bodies.size());
    island.AddBody(id, body, world, step);
  };
  for (size_t j : island.joint_members) add(joints_[j].a, joints_[j].body_a);
  for (size_t j : island.joint_members) add(joints_[j].b, joints_[j].body_b);
  for (size_t k : island.members) {
    add(kept_[k].a, kept_[k].body_a);
    add(kept_[k].b, kept_[k].body_b);
  }
  for (size_t k : island.members) {
    const Kept& kept = kept_[k];
    island.first_row.push_back(island.rows.size());
    const int ia = kept.a >= 0 ? local_[kept.a] : -1;
    const int ib = kept.b >= 0 ? local_[kept.b] : -1;
    ContactJointRows(kept.contact, kept.body_a, kept.body_b, ia, ib, world, step, &island.rows);
  }
  island.first_row.push_back(island.rows.size());
  bool known = true;
  for (size_t j : island.joint_members) {
    const KeptJoint& kept = joints_[j];
    const int ib = kept.b >= 0 ? local_[kept.b] : -1;
    known = known && JointRows(kept.joint, local_[kept.a], ib, kept.frame, world, step,
                               &island.rows, !reduced);
    if (known && reduced) AddTreeEdge(kept.joint, local_[kept.a], ib);
  }
  for (int id : island.ids) local_[id] = -1;
  const int count = static_cast<int>(island.bodies.size());
  return known && (!reduced || OrientTree(count, island.edges, &island.tree, &island.child_edge));
}

// a hinge or slider between island bodies `first` and `second` (-1: the world) as an edge of the
// reduced step's tree (in place of the rows that hold it together)
void ObjectIslands::AddTreeEdge(dJointID joint, int first, int second) {
  Island& island = *island_;
  const int type = dJointGetType(joint);
  if (type != dJointTypeHinge && type != dJointTypeSlider) return;
  TreeEdge edge{first, second, {}};
  dVector3 axis, anchor;
  if (type == dJointTypeHinge) {
    edge.link.kind = TreeLink::Kind::kHinge;
    dJointGetHingeAxis(joint, axis);
    dJointGetHingeAnchor(joint, anchor);
    edge.link.anchor = ToVec3(anchor);
  } else {
    edge.link.kind = TreeLink::Kind::kSlider;
    dJointGetSliderAxis(joint, axis);
  }
  edge.link.axis = ToVec3(axis);
  island.edges.push_back(edge);
  island.edge_joints.push_back(joint);
}

// ODE's solver takes the island: its contact joints are made (its robot joints stay enabled)
void ObjectIslands::HandBack(dWorldID world, dJointGroupID group) {
  for (size_t k : island_->members) {
    const Kept& kept = kept_[k];
    dJointID joint = dJointCreateContact(world, group, &kept.contact);
    dJointAttach(joint, kept.body_a, kept.body_b);
    if (kept.feedback != nullptr) dJointSetFeedback(joint, kept.feedback);
  }
}

// body k's constraint wrench M (v' − v_free) / h into its accumulators, so that ODE's step
// lands on the solver's velocity (λ itself is as sensitive to v' as 1 / cfm: a velocity error of
// 1e-12 m/s is 1e-3 N on a hard row, and h M⁻¹ Σ Jᵀλ would not land on v')
void ObjectIslands::Island::AddWrench(size_t k, double step) const {
  const NewtonBody& body = bodies[k];
  const Vec6 change = result.velocity[k] - body.free_velocity;
  const Vec3 force = body.mass * change.head<3>() / step;
  const Vec3 torque = body.inertia * change.tail<3>() / step;
  dBodyAddForce(odes[k], force.x(), force.y(), force.z());
  dBodyAddTorque(odes[k], torque.x(), torque.y(), torque.z());
}

// the kept contacts' feedback as ODE reports it, from λ
void ObjectIslands::Island::ReportFeedback(const std::vector<Kept>& kept) const {
  for (size_t m = 0; m < members.size(); ++m) {
    dJointFeedback* feedback = kept[members[m]].feedback;
    if (feedback == nullptr) continue;
    Vec6 first = Vec6::Zero(), second = Vec6::Zero();
    for (size_t i = first_row[m]; i < first_row[m + 1]; ++i) {
      first += result.force[i] * rows[i].ja;
      second += result.force[i] * rows[i].jb;
    }
    for (int k = 0; k < 3; ++k) {
      feedback->f1[k] = first(k);
      feedback->t1[k] = first(3 + k);
      feedback->f2[k] = second(k);
      feedback->t2[k] = second(3 + k);
    }
  }
}

}  // namespace lamina::core
