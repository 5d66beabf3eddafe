// SPDX-License-Identifier: MIT
// A step's own joint drift taken back in the step, as SHAKE does (Ryckaert, Ciccotti & Berendsen
// 1977; for rigid bodies: the constraint impulse found at the start of the step that puts the
// bodies on their joints at its end).
//
// Why: ODE's step holds a joint's anchors at zero relative velocity at the start of the step,
// then moves each body along a straight line while it turns, so a hinge's two anchors part by
// about ½(ωh)²·r in the step, and the world's ERP closes the gap only in the next step. The joint
// rides open by that much (0.8 mm on the 40-link chain at 1 ms, where a link's end whips), and a
// pendulum swings on a radius longer by it (accuracy: chain, bridge_160, pendulum). Klamp't has
// the same gap; Lamina takes it back (the world's `jointStabilization`, on by default). Joint
// coordinates (reduced_basis.h, joint_projection.h) have no gap to take back.
//
// What: after the step, the impulse Jᵀλ along the joints' rows as they were at the start of the
// step (J₀: the bodies' arms and the joints' directions there) whose velocity change, carried
// through the step, takes back the drift the step left (the gaps beyond those its rows aimed at:
// a gap from before the step is the ERP's to close): Δq = M⁻¹J₀ᵀλ moves the bodies and Δq/h is
// added to their velocities, as if the step's own solve had asked for it. A correction along the
// rows of the start (not those of the end, which a plain projection of the positions would use) is
// what keeps the energy: measured on the pendulum at 1 ms, moving the bodies onto their joints
// along the end's rows and leaving the velocities lost 3 % of the swing energy in 10 s (and
// halved with h: first order); this keeps it (the last period's mean energy 1.4e-9 of the swing
// energy from the first's at 1 ms, ODE's step alone 9.8e-7; measured before the rod followed its
// arc, below, with which it is 2.1e-9). The cost: a profile factorization
// and a few solves over the joints' bodies every step, as much as ODE's own dense solve on small
// systems (docs/simulator.md: 1.13 to 1.87 times the CPU time of ODE alone on the accuracy
// scenes' chains and pendulum).
//
// A body on a hinge to the world (the pendulum, a door) is first carried along its arc
// (ArcOffset): ODE moved its centre of mass along the chord h·v while it turned the body by
// exp(h·ω̂), and a body turning about a fixed point goes where that turn about the point puts it,
// its velocity turned with it. That leaves its hinge only what the step's solve did not hold (the
// world's CFM: 9.8e-9 m on the pendulum at 1 ms against a chord's 3.7e-6 m; 1e-12 m with CFM
// 1e-10), which one round of the correction takes back, and the step is then the step in joint
// coordinates for it, symplectic Euler on its angle. The correction along the
// rows of the start alone closes the same drift but lands the centre at the chord's length from
// where it started, so the angle advances by asin(h·ω) rather than h·ω per step: the pendulum's
// period came out 9.7e-7 of T short at 1 ms (numerics' bar (ω₀h)²/24 = 6.1e-7; now 3.1e-7, as
// symplectic Euler on the angle). A body hinged to another moving body keeps the correction only.
//
// Rows: what JointGap counts (joint_projection.h), a hinge's axis point carried by each body
// (3 rows), a slider's or fixed joint's child centre of mass off the line or the point the parent
// carries it along (2 or 3 rows), closed; and the rows that keep the rotation (a
// hinge's 2 across its axis, a slider's or fixed joint's 3), held at no change, so that the
// correction does not tilt a hinge or turn a slider.
//
// How: each round solves (M + w·J₀ᵀJ₀) Δq = −w·J₀ᵀc with c the gaps measured at the bodies'
// current poses (zero for the rotation rows) and w = kPenalty · (largest mass): the least
// M-weighted motion along the rows up to a relative 1/w, and well posed where J₀ loses rank (a
// straight bridge, whose hinges are collinear). Every round's Δq is M⁻¹J₀ᵀ of some λ, so the sum
// is too. The matrix has a 6 × 6 block per moving body and one off-diagonal block per joint
// between two: it is factored once per step in its profile (profile_cholesky.h) in the bodies'
// order (a chain listed end to end is a band), and each round is one solve. Each round leaves
// about as much of the drift as the joints turned in the step (the rows of the start against the
// poses of the end), 1e-3 at 1 rad/s and 1 ms: one or two rounds.
//
// Units: m, kg, kg·m², rad, s. Body states at the centre of mass, world axes (BodyState).
#pragma once

#include <vector>

#include "core/math_types.h"
#include "core/sim/joint_projection.h"
#include "core/sim/profile_cholesky.h"
#include "core/sim/sim_state.h"

namespace lamina::core {

/// A body the joints hold. A body that does not move (static, kinematic, asleep, a robot's link)
/// still carries its joints' points but is not moved.
struct StabilizedBody {
  BodyState start;                  ///< at the start of the step (poses only are read)
  BodyState state;                  ///< at its end: moved, and its velocities changed, in place
  double mass = 1.0;                ///< kg (unused when !moves)
  Mat3 inertia = Mat3::Identity();  ///< kg·m², about the centre of mass, in the body's axes
  bool moves = true;
};

/// A joint between bodies[parent] (−1: the world at the origin) and bodies[child], placed as
/// `placement` says (joint_projection.h: parent's and child's axes, as built).
struct StabilizedJoint {
  int parent = -1;
  int child = 0;
  JointPlacement placement;
};

/// What ODE's step leaves of a body turning about a world hinge's fixed axis, taken back: the
/// step moved its centre of mass along the chord h·v while it turned the body by exp(h·ω̂) (finite
/// rotation), so the hinge's point the body carries left the axis by about ½(ωh)²·r. A body
/// turning about a fixed point travels the arc instead: returns the move from the chord's end to
/// the arc's, (exp(h·ω̂) − I − h·ω̂)·(c₀ − p₀), with `arm` = c₀ − p₀ the centre of mass from the
/// hinge's point at the start of the step and `angular_velocity` ω the body's after the step
/// (m). Its velocity turns with it: `velocity_change` (m/s) is ω × (exp(h·ω̂) − I)·(c₀ − p₀), so
/// the centre's velocity keeps its length and stays the rigid motion's about the point. Both are
/// zero when ω is. This is the step in joint coordinates for such a body (symplectic Euler on
/// its angle); for a body hinged to another moving body the drift is left to the correction.
Vec3 ArcOffset(const Vec3& arm, const Vec3& angular_velocity, double step, Vec3* velocity_change);

class JointStabilizer {
 public:
  static constexpr double kPenalty = 1e6;  ///< w / (largest mass)
  static constexpr int kMaxRounds = 7;
  /// The drift counts as closed within the tolerance or within this fraction of what the step
  /// left (the rest is the ERP's: 8e-8 of a link on the whipping chain at 1 ms).
  static constexpr double kReduction = 1e-4;
  /// A round must leave at most this fraction of the drift it started from (each leaves about
  /// as much as the joints turned in the step, 1e-3 at 1 rad/s and 1 ms), or the correction is
  /// given up (a straight bridge's rounds leave about half).
  static constexpr double kSlowRound = 0.25;

  struct Result {
    double gap_before = 0.0;  ///< m, the widest drift the step left
    double gap_after = 0.0;   ///< m, the widest drift left (gap_before when not applied)
    int rounds = 0;           ///< rounds taken (0: every gap was within the tolerance)
    bool applied = false;     ///< the bodies were moved and their velocities changed
  };

  /// Takes back the drift a step of `step` s left in the joints: each joint's gap vector at the
  /// end less the one the step's rows aimed at, (1 − erp) of the gap at the start with the
  /// world's ERP `erp` (a gap a joint had before the step, as after a teleport or an edit, stays
  /// the ERP's to close, at its pace). Rounds run until the widest drift is within `tolerance`
  /// (m) or kReduction of what the step left, at most kMaxRounds of them. When it does not close
  /// so far (a round slower than kSlowRound, or too few rounds: joints that turned fast in the
  /// step, rows near a singular pose such as a straight bridge's, where the drift is of second
  /// order in a motion the rows do not see), or the matrix is not positive definite, nothing is
  /// changed and the gaps are left to ODE's ERP, as without.
  Result Stabilize(std::vector<StabilizedBody>* bodies, const std::vector<StabilizedJoint>& joints,
                   double step, double erp, double tolerance);

 private:
  struct Row {
    int joint = 0;
    int gap = -1;  ///< the gap direction it takes (0..2), or −1: a rotation row, held at 0
    ProfileCholesky::Column parent, child;  ///< J₀: linear then angular (world axes)
  };
  void FollowWorldHinges(std::vector<StabilizedBody>* bodies,
                         const std::vector<StabilizedJoint>& joints, double step);
  void BuildRows(const std::vector<StabilizedBody>& bodies,
                 const std::vector<StabilizedJoint>& joints);
  void AddJointRows(int joint, const JointPlacement& placement, const BodyState& parent,
                    const BodyState& child);
  double MeasureGaps(const std::vector<StabilizedBody>& bodies,
                     const std::vector<StabilizedJoint>& joints);
  void Profile(const std::vector<StabilizedBody>& bodies,
               const std::vector<StabilizedJoint>& joints);
  bool Factor(const std::vector<StabilizedBody>& bodies,
              const std::vector<StabilizedJoint>& joints);
  void AddRowBlocks(int block, const ProfileCholesky::Column& jacobian);
  void SolveRound(std::vector<StabilizedBody>* bodies, const std::vector<StabilizedJoint>& joints);

  std::vector<char> followed_;  ///< per body: carried along a world hinge's arc this step
  std::vector<int> block_;      ///< per body: its block, or −1 when it does not move
  std::vector<int> first_;      ///< per block: first block of its row's profile
  std::vector<Row> rows_;
  std::vector<Vec3> intended_;  ///< per joint: the gap vector the step aimed at (world)
  std::vector<Vec3> gaps_;      ///< per joint: its drift at the current poses, in J₀'s directions
  std::vector<BodyState> kept_;  ///< the step's poses, put back when the gaps do not close
  double w_ = 0.0;
  ProfileCholesky matrix_;
  Eigen::VectorXd step_, moved_;  ///< a round's Δq; the sum of the rounds' (6 per block)
};

}  // namespace lamina::core
