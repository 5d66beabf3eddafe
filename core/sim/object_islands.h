// SPDX-License-Identifier: MIT
// The share of a step that Lamina's own solvers take: under solver "newton" every island of free
// rigid objects, robots and their contacts (newton_solver.h); under the exact solver ("step")
// the islands where dWorldStep's dense LCP is the costly answer: a robot's island with the fixed
// world, given one Newton step and, when that does not settle it, solved directly
// (direct_solver.h: dWorldStep's answer without its dense matrix of every row), and an island of
// free objects with many contacts, solved by the Newton solver (a ball on a mesh with 20 contacts:
// 60 rows in dWorldStep's matrix, 6 velocities in Newton's). Below, "the solver" is whichever takes
// the island.
//
// - The contact joints of such an island are kept as dContacts instead of being created in ODE.
//   After the solve (newton_solver.h) the island's bodies are set aside: disabled for ODE's step,
//   which steps only the rest of the world, then integrated at the solver's velocity v' as ODE's
//   step integrates a body (free_body_step.h: the pose to the last bit) and enabled again. Their
//   free velocity takes ODE's implicit gyroscopic term. (A body ODE must integrate itself, one it
//   would step through an enabled joint or with damping: StepsItself, gets its constraint wrench
//   M (v' − v_free) / h in its force accumulators instead, so that ODE's step lands on v'.)
// - The rows are ODE's own (ContactJointRows: ode/src/joints/contact.cpp, getInfo2, including
//   the swap of a joint whose first body is the fixed world), so the answer is dWorldStep's to the
//   solver's tolerance where ODE's Dantzig solver is exact (newton_solver.h: where friction
//   saturates, this answer is the consistent one).
// - A robot's joints and motors (ode_robot.h) are kept too: their rows are ODE's
//   (ode_joint_rows.h), and when the island's solve converges the joints are disabled for ODE's
//   step, and enabled again after it (Restore); the bodies are set aside as above.
// - An island with a body held by another persistent ODE joint (a world joint, the mouse
//   spring), with a joint outside what ode_joint_rows.h replicates, or whose solve does not
//   converge gets its ODE joints as before, and ODE's solver takes it in the same step. (Under
//   the Newton solver in joint coordinates the world's hinges and sliders between free rigid
//   objects, without friction, are kept like a robot's joints: Simulator::KeepWorldJoints.)
// - Contact feedback: a kept contact fills its dJointFeedback (force and torque on each body, as
//   ODE reports them) from λ.
// Units: SI; forces in N, torques in N·m about each body's centre of mass, world axes.
#pragma once

#include <memory>
#include <vector>

#include "core/sim/ode_fwd.h"
#include "core/sim/ode_joint_rows.h"

namespace lamina::core {

/// The Newton solver's islands of one step, by world id.
class ObjectIslands {
 public:
  struct Statistics {
    long long islands = 0;           ///< islands taken (by either solver)
    long long fallbacks = 0;         ///< islands handed back to ODE's solver (no convergence)
    long long newton_islands = 0;    ///< islands the Newton solver was given first
    long long newton_fallbacks = 0;  ///< of those, handed back to ODE's solver
    /// of those, not converged but too large to hand back (kMostHandBackRows): relaxed instead
    /// (kRelaxSweeps)
    long long unconverged = 0;
    long long iterations = 0;         ///< Newton steps in all
    long long factorizations = 0;     ///< Hessians the Newton solver factored (newton_solver.h)
    long long direct_islands = 0;     ///< islands the direct solve was given
    long long direct_fallbacks = 0;   ///< of those, not settled (then ODE's)
    long long reduced_islands = 0;    ///< robot islands given the reduced step
    long long reduced_fallbacks = 0;  ///< of those, not converged (then the Newton solver's)
  };

  /// Newton steps a large robot's island gets before the direct solve (SolveNewton): two while
  /// fewer than two of its Newton solves in a row failed, one after that. A robot landing on a
  /// plane settles in two where one does not (ATHLETE's first 1.5 s: 16 % fewer instructions,
  /// 47 direct solves instead of 394), a robot on rough ground seldom in either, and there the
  /// second step is only paid until two failures (ATHLETE on fractal terrain: 1.4 % fewer; two
  /// steps always: 7.6 % more).
  static constexpr int kNewtonStepsBeforeDirect = 1;
  static constexpr int kNewtonStepsWhileSettling = 2;
  static constexpr int kFailuresBeforeOneNewtonStep = 2;
  /// After a large robot's Newton step has not settled its island n times in a row, its island
  /// goes straight to the direct solve for the next min(2^(n−1), kMostDirectSteps) steps: on
  /// rough ground, where the Newton step seldom settles, it is not paid every step.
  static constexpr int kMostDirectSteps = 16;
  /// Rounds of friction bounds a reduced step takes at once before it damps them
  /// (NewtonOptions::undamped_rounds): wheels landing sliding swing from round to round.
  static constexpr int kUndampedReducedRounds = 10;
  /// Newton steps a reduced step takes before the direct solve (SolveReduced).
  static constexpr int kReducedNewtonSteps = 4;
  /// Rows above which an island (but a large robot's) that the Newton solver has not settled is
  /// not handed to dWorldStep: ODE's pivoting LCP is dense, its time grows as the cube of the rows
  /// and its memory as their square (measured on pyramids of boxes, one dWorldStep a step: 430
  /// rows 12 ms, 1190 rows 0.33 s, 2330 rows 3.1 s; the 30,000 rows of a 1,275-box pyramid
  /// asked for 7 GB). Such an island gets more Newton steps first (NewtonBudget); when they do
  /// not settle it either, kRelaxSweeps Gauss–Seidel sweeps solve it from no force
  /// (row_relaxation.h: forces inside their bounds, the velocities they make), it is counted in
  /// Statistics::unconverged, and its step is flagged (Simulator: "contact unreliable").
  static constexpr size_t kMostHandBackRows = 1000;
  /// QuickStep's default is 20; the 210-box pyramid given one Newton step a time step and 50
  /// sweeps stands (tests/scenes/newton_islands_test.cpp).
  static constexpr int kRelaxSweeps = 50;

  ObjectIslands();
  ~ObjectIslands();
  ObjectIslands(const ObjectIslands&) = delete;
  ObjectIslands& operator=(const ObjectIslands&) = delete;

  /// Starts a step over world ids 0 … count-1. `exact`: the islands are the exact solver's
  /// rather than the Newton solver's: an island without a robot joint is the Newton solver's
  /// when it holds at least `newton_contacts` kept contacts and dWorldStep's otherwise (0:
  /// always the Newton solver's). Under both, an island with a robot joint and at least
  /// `direct_bodies` bodies (0: none) that kNewtonStepsBeforeDirect Newton steps do not settle
  /// is solved directly (the same law, without twenty Newton steps over a long chain), and goes
  /// to dWorldStep when that does not settle either (every robot the exact solver keeps is such
  /// a one).
  void Begin(int count, bool exact = false, int direct_bodies = 0, int newton_contacts = 0);
  /// Whether a large robot's island (`direct_bodies` above) gets kNewtonStepsBeforeDirect
  /// Newton steps before the direct solve, under both solvers (on by default): where few rows
  /// change their law, as on a humanoid standing on a plane, one Newton step is the cheapest
  /// exact answer. Off: the direct solve alone.
  void SetRobotNewtonStep(bool newton) { robot_newton_ = newton; }
  /// Whether the Newton solver (not the exact one) takes a robot's island in its generalized
  /// velocities (reduced_basis.h: one unknown per hinge or slider and six per free body, no
  /// joint rows; the world's `jointCoordinates`, off by default). The caller then places the
  /// robot's bodies on their joints after ODE's step (SolvedReduced,
  /// OdeRobot::ProjectOntoJoints). An island whose joints do not form a tree, or whose reduced
  /// step does not settle, is solved over every body as without.
  void SetReducedRobots(bool reduced) { reduced_ = reduced; }
  /// Newton steps every island but a large robot's gets at most (0: NewtonBudget's own choice):
  /// for tests and comparisons.
  void SetNewtonBudget(int steps) { newton_budget_ = steps; }
  /// After Solve: whether `joint` (a kept robot joint) was in an island given the reduced step.
  bool SolvedReduced(const dxJoint* joint) const;
  /// A hinge or slider of an island given the reduced step, and which of its bodies is the child
  /// in the island's tree (reduced_basis.h OrientTree).
  struct TreeJoint {
    const dxJoint* joint;
    bool first_is_child;
  };
  /// After Solve: those joints, every one after the joint that carries its parent.
  const std::vector<TreeJoint>& reduced_tree() const { return reduced_tree_; }
  /// `id`'s island is ODE's (a body with a persistent ODE joint, dragged, a robot the Newton
  /// solver does not take).
  void MarkOde(int id) { ode_[Root(id)] = 1; }
  /// A contact between two free bodies: one island.
  void Link(int a, int b);
  /// True when `id` (a free body after every Link and MarkOde) is in a Newton island.
  bool Takes(int id) { return !ode_[Root(id)]; }
  /// Keeps a contact joint between `a` and `b` (world ids; -1 or a body outside the islands for
  /// the fixed world or a kinematic body), reporting into `feedback` when not null.
  void Keep(const dContact& contact, int a, int b, dxBody* body_a, dxBody* body_b,
            dJointFeedback* feedback);
  /// Keeps a robot's (or a world's) joint or motor `joint` between its first body (world id `a`)
  /// and its second (`b`, -1: the world), and links them into one island. `frame`:
  /// ode_joint_rows.h. Joints kept in children-first order keep the solver's matrix narrow.
  void KeepJoint(dxJoint* joint, int a, int b, const JointFrame& frame);
  /// Solves every island of the kept contacts and joints, adds the forces to the bodies and
  /// disables the kept joints of the solved islands; an island that does not converge gets its
  /// contact joints in `group` (and keeps its joints), unless it has more than
  /// kMostHandBackRows rows (then Gauss–Seidel sweeps solve it: row_relaxation.h).
  void Solve(dxWorld* world, dxJointGroup* group, double step);
  /// Just before ODE's step: the bodies of the islands Solve solved are disabled in ODE, which
  /// then steps only the rest of the world (StepsItself says which: nearly all).
  void SetAside();
  /// After ODE's step: those bodies integrated at the solver's velocity as ODE's step would
  /// (free_body_step.h, to the last bit of the pose), their accumulators cleared, and enabled.
  void StepSetAside(double step);
  /// After ODE's step (or a failure before it): the joints Solve disabled are enabled again,
  /// and bodies still set aside (a failed step: not integrated).
  void Restore();
  const Statistics& statistics() const { return statistics_; }

 private:
  struct Kept;       ///< a kept contact joint (object_islands.cpp)
  struct KeptJoint;  ///< a kept robot joint (object_islands.cpp)
  struct Island;     ///< one island's solve and its scratch (object_islands.cpp)
  int Root(int id);
  int IslandOf(size_t item);  ///< item: a kept contact, then kept joints after them
  void SolveIsland(dxWorld* world, dxJointGroup* group, double step);
  bool SolveDirectly(double step);
  bool SolveNewton(int max_iterations, double step);
  int NewtonBudget() const;
  static unsigned long long IslandKey(const std::vector<int>& ids);
  bool SolveLargeRobot(double step);
  /// The count of steps to go straight to the direct solve, and of failed Newton steps in a
  /// row, of a large robot (keyed by its first kept joint).
  struct RobotBackoff {
    const dxJoint* robot = nullptr;
    int direct_steps = 0;
    int failures = 0;
  };
  RobotBackoff& BackoffOf(const dxJoint* robot);
  static bool NewtonDue(RobotBackoff* backoff);
  static void RecordNewton(RobotBackoff* backoff, bool settled);
  bool BuildIsland(dxWorld* world, double step, bool reduced);
  void AddTreeEdge(dxJoint* joint, int first, int second);
  bool SolveReduced(dxWorld* world, double step);
  void Finish(double step, bool reduced);
  static bool StepsItself(dxBody* body);
  void HandBack(dxWorld* world, dxJointGroup* group);

  std::vector<int> parent_;
  std::vector<char> ode_;
  std::vector<Kept> kept_;
  std::vector<KeptJoint> joints_;
  std::vector<dxJoint*> disabled_;
  struct SetAsideBody {
    dxBody* body;
    Vec6 velocity;  ///< the solver's
  };
  std::vector<SetAsideBody> set_aside_;
  std::vector<int> local_;  ///< world id -> index in the island being solved, or -1
  std::unique_ptr<Island> island_;
  Statistics statistics_;
  bool exact_ = false;
  int direct_bodies_ = 0;                       ///< Begin
  int newton_contacts_ = 0;                     ///< Begin
  bool robot_newton_ = true;                    ///< SetRobotNewtonStep
  bool reduced_ = false;                        ///< SetReducedRobots
  int newton_budget_ = 0;                       ///< SetNewtonBudget
  std::vector<const dxJoint*> reduced_joints_;  ///< SolvedReduced
  std::vector<TreeJoint> reduced_tree_;         ///< reduced_tree
  std::vector<RobotBackoff> backoff_;
};

}  // namespace lamina::core
