// SPDX-License-Identifier: MIT
// The step guard: whether a tentative step must be retaken smaller (adaptive time stepping with
// rollback, Klamp't's design), and whether it blew up (energy from nowhere, non-finite states).
//
// Rollback (NeedsRollback): a tentative step is retaken in halves when it let a pair
// interpenetrate that had layer to spare before, or when it used up more than half of a pair's
// layer at once (more than half of what remained, and a noticeable part of the layer: noise at a
// settled contact is no reason). An interpenetration under a layer already pressed through (a
// soft layer resting on its core), or an old one, is reported (unreliable) but never rolled back:
// that would roll back forever. Klamp't rolls back on any overlap beyond half the padding.
//
// Stability (energy_guard.h has the rules and their differences from Klamp't): the kinetic energy
// of every freely moving rigid object is checked after each accepted step against what gravity,
// applied forces, held wrenches and its contacts can supply (a body pushed by a kinematic body
// or held by the mouse spring is left out); a body whose energy overflows a double is stopped
// before ODE steps (ODE would fail inside its step); a step that leaves a state non-finite is
// undone once with the culprits stopped (a robot's culprit is the whole robot). Robots have a
// check of their own, on their joints (robot_guard.h).
#pragma once

#include <functional>
#include <vector>

#include "core/sim/body_table.h"
#include "core/sim/contact_set.h"
#include "core/sim/energy_guard.h"
#include "core/sim/sim_state.h"

namespace lamina::core {

/// A pair whose layer moved less than this fraction of its thickness in a step has settled.
inline constexpr double kSettledLayerFraction = 0.1;
/// A layer with less than this fraction of its thickness left is pressed through (resting on the
/// geometry under it).
inline constexpr double kPressedThroughFraction = 0.01;

/// True when the step from the contacts `before` to `after` must be retaken smaller (rules
/// above); `unreliable` becomes true when some pair of `after` interpenetrates. Both lists are
/// in broad-phase order (sorted by their id pairs): one merge, O(P).
bool NeedsRollback(const std::vector<ContactPair>& before, const std::vector<ContactPair>& after,
                   bool* unreliable);

/// The blended layer stiffness of a pair (N/m; inf for a hard contact).
using PairStiffness = std::function<double(const ContactPair&)>;

/// The energy each body may gain from its contacts of `pairs` within one step without anything
/// being wrong (J): the position correction of each overlap (at most ERP = 1: speed depth/step),
/// the friction anchors' correction, and the spring energy ½ k depth² of soft layers. One pass
/// over the pairs for every body at once; `masses` (kg) and `allowances` by body id.
void ContactEnergyAllowances(const std::vector<ContactPair>& pairs,
                             const std::vector<double>& masses, const PairStiffness& stiffness,
                             double step, std::vector<double>* allowances);

class StepGuard {
 public:
  /// The state at the start of the tentative step (CaptureBodyState fills it).
  SimState& rollback_state() { return rollback_state_; }
  const SimState& rollback_state() const { return rollback_state_; }

  /// Bodies whose energy is unknown (just set) take it from their current state, so that the set
  /// itself is not mistaken for a blow-up.
  static void MeasureUnknownEnergies(BodyTable* bodies);
  /// Stops every freely moving body whose energy overflows; the number stopped. Each of these
  /// corrections appends the world ids of the bodies it slowed or stopped to `ids` (when given).
  static int StopOverflowingBodies(BodyTable* bodies, std::vector<int>* ids = nullptr);
  /// After a step that left a non-finite state: back to rollback_state() with the bodies that blew
  /// up stopped (the number of them; every link of a robot one of whose links blew up, as
  /// robot_guard.h says); -1 when nothing can be recovered (nothing blew up, or the state before
  /// was not finite). `restore` restores a SimState.
  int RecoverFromFailedStep(BodyTable* bodies, const std::function<void(const SimState&)>& restore,
                            std::vector<int>* ids = nullptr);
  /// Checks the accepted step of length `step`: every rigid object over its energy allowance is
  /// slowed down (energy_guard.h); the number of corrected bodies. `before` are the contacts the
  /// step was taken with.
  int CorrectInstabilities(BodyTable* bodies, const std::vector<ContactPair>& before,
                           const PairStiffness& stiffness, const Vec3& gravity, double step,
                           std::vector<int>* ids = nullptr);

 private:
  std::vector<char> BlownUp(const BodyTable& bodies) const;
  void MarkPushed(const BodyTable& bodies, const std::vector<ContactPair>& before);
  void CollectSamples(BodyTable* bodies, const std::vector<ContactPair>& before,
                      const PairStiffness& stiffness, const Vec3& gravity, double step);

  SimState rollback_state_;
  struct {
    std::vector<char> pushed;  ///< per body: touched a kinematic body this step
    std::vector<BodyEnergySample> samples;
    std::vector<int> checked;                ///< body id of each sample
    std::vector<double> masses, allowances;  ///< by body id
  } scratch_;
};

}  // namespace lamina::core
