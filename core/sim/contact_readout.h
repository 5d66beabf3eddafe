// SPDX-License-Identifier: MIT
// "Its contacts now": what an inspector shows of one body's contacts at the current state, one
// entry per partner body it touches: the blended surface of the pair exactly as the contact rows
// use it, the rule that produced each value (naming the inputs and whose they are),
// the contact count, overlap and padding sum, the normal force of the last sub-step and the
// pair's soft-contact ERP/CFM.
//
// One source of truth: the values come from Simulator::PairSurface and Simulator::PairContactLaw,
// the same functions the contact joints are built from (simulator_contacts.cpp), so the readout
// cannot drift from what ODE is given. The rule texts come from the pure Describe* functions
// below, which follow BlendSurfaces' branches (surface_blend.h) one for one.
//
// Units: friction and restitution are dimensionless, rolling and spinning friction m, stiffness
// N/m, damping N·s/m, lengths m,
// forces N, ERP dimensionless, CFM m/(N·s) (ODE's units for a contact row).
// Sign convention: the normal force is on `body_id` from the partner, measured along the contact
// normals pointing into `body_id` (contact_feedback.h), so a partner that pushes gives > 0.
// Klamp't has no such readout; its ContactFeedback reports forces but neither the blend nor
// the rules.
#pragma once

#include <string>
#include <vector>

#include "core/sim/simulator.h"

namespace lamina::core {

/// One blended surface value and where it came from.
struct BlendReadout {
  double value = 0.0;    ///< what the contact rows use (the pair's blend)
  double own = 0.0;      ///< the inspected body's surface value
  double partner = 0.0;  ///< the partner's surface value
  std::string rule;      ///< e.g. "harmonic mean of 0.5 (box) and 1 (floor)"
};

/// The contacts of the inspected body with one partner at the current state.
struct PairReadout {
  int partner = -1;  ///< world id
  std::string
      partner_name;  ///< its name in the world, or "terrain 0", "object 2", "link 3 of robot 0"
  BlendReadout friction;     ///< Coulomb coefficient
  BlendReadout restitution;  ///< coefficient of restitution (hard contacts only bounce)
  BlendReadout stiffness;    ///< N/m; inf = rigid
  BlendReadout damping;      ///< N·s/m; inf = rigid
  BlendReadout rolling;      ///< rolling friction, m (0: off)
  BlendReadout spinning;     ///< spinning friction, m (0: off)
  int contact_count = 0;     ///< after merging and clustering
  double max_depth = 0.0;    ///< deepest boundary-layer overlap (m)
  double padding_sum = 0.0;  ///< the pair's padding sum (m); the layers overlap by max_depth of it
  /// Σ f_i·n_i over the last sub-step's contacts (N); only when contact feedback is recorded for
  /// the pair (Simulator::EnableContactFeedback), 0 otherwise.
  double normal_force = 0.0;
  bool normal_force_known = false;
  std::string normal_force_note;  ///< why it is not known ("" when it is)
  /// The pair's soft contact for one simulation step (the pair's whole k and c at its deepest
  /// overlap; each contact row takes its pressure share of them, contact_rows.h).
  bool soft = false;  ///< false: a hard contact with the world's ERP and CFM
  double erp = 0.0;   ///< 0 when hard
  double cfm = 0.0;   ///< m/(N·s); 0 when hard
  std::string law;    ///< "soft: ERP 0.004, CFM 5e-06" or "hard"
};

/// One entry per body touching `body_id` now (in sim.contact_pairs(), on either side), in the
/// pairs' order. Empty for a body that touches nothing and for an id that is not a body.
std::vector<PairReadout> ReadContacts(const Simulator& sim, int body_id);

/// The rules as text. `own`/`partner` are the two bodies' values, the names say whose they are.
/// Each follows the branch BlendSurfaces takes for the same inputs.
std::string DescribeRestitution(double own, double partner, const std::string& own_name,
                                const std::string& partner_name);
std::string DescribeFriction(double own, double partner, const std::string& own_name,
                             const std::string& partner_name);
/// Rolling or spinning friction (finite): the harmonic mean, off when either side is 0.
std::string DescribeResistance(double own, double partner, const std::string& own_name,
                               const std::string& partner_name);
/// Stiffness (symbol "k") or damping ("c"): layers in series.
std::string DescribeLayer(const char* symbol, double own, double partner,
                          const std::string& own_name, const std::string& partner_name);

/// A world id's name: the element's own, or its kind and index when it has none.
std::string BodyLabel(const WorldDesc& world, int id);
/// "'box' (id 3)", "'box' (id 3) and 'lid' (id 4)", "'a' (id 1), 'b' (id 2), 'c' (id 3) and
/// 2 more": bodies named in messages.
std::string BodiesText(const WorldDesc& world, const std::vector<int>& ids);

}  // namespace lamina::core
