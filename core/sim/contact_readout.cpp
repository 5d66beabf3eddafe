// SPDX-License-Identifier: MIT
// One body's contacts now, for an inspector (see contact_readout.h).
#include "core/sim/contact_readout.h"

#include <cmath>

#include "core/number_text.h"
#include "core/sim/contact_rows.h"

namespace lamina::core {

namespace {

// "0.5 (box)"
std::string Named(double value, const std::string& name) {
  return FormatDouble(value) + " (" + name + ")";
}

std::string ElementName(const std::string& name, const char* kind, int index) {
  return name.empty() ? std::string(kind) + " " + std::to_string(index) : name;
}

// the surface a body has in the simulated description (every live edit included)
const SurfaceDesc& SurfaceOf(const WorldDesc& world, int id) {
  const WorldId where = world.Resolve(id);
  if (where.kind == WorldId::Kind::kTerrain) return world.terrains[where.index].sim.surface;
  if (where.kind == WorldId::Kind::kRigidObject) return world.objects[where.index].sim.surface;
  return world.robots[where.index].links[where.link].sim.surface;
}

BlendReadout Blend(double value, double own, double partner, std::string rule) {
  return {value, own, partner, std::move(rule)};
}

// the body's side of the pair and the partner, or -1 when the pair does not touch body_id
int PartnerIn(const ContactPair& pair, int body_id) {
  if (pair.contacts.empty()) return -1;
  if (pair.a == body_id) return pair.b;
  return pair.b == body_id ? pair.a : -1;
}

// Σ f_i·n_i on body_id from partner in the last sub-step, if feedback is recorded for the pair
void ReadNormalForce(const Simulator& sim, int body_id, int partner, PairReadout* out) {
  if (sim.feedback().Find(body_id, partner) == nullptr) {
    out->normal_force_note = "contact feedback is not recorded for this pair";
    return;
  }
  out->normal_force_known = true;
  for (const FeedbackContact& contact : sim.GetContacts(body_id, partner)) {
    out->normal_force += contact.force.dot(contact.normal);
  }
}

void ReadLaw(const Simulator& sim, const ContactPair& pair, PairReadout* out) {
  const PairLaw law = sim.PairContactLaw(pair, sim.sim_step());
  out->soft = law.soft.soft;
  out->erp = law.soft.erp;
  out->cfm = law.soft.cfm;
  if (!law.soft.soft) {
    out->law = "hard";
  } else if (!law.pushes) {
    out->law = "no force (k = 0 and c = 0)";
  } else {
    out->law = "soft: ERP " + FormatDouble(law.soft.erp) + ", CFM " + FormatDouble(law.soft.cfm);
  }
}

void ReadSurface(const Simulator& sim, int body_id, int partner, PairReadout* out) {
  const BlendedSurface blend = sim.PairSurface(body_id, partner);
  const SurfaceDesc& own = SurfaceOf(sim.world(), body_id);
  const SurfaceDesc& other = SurfaceOf(sim.world(), partner);
  const std::string me = BodyLabel(sim.world(), body_id);
  const std::string them = out->partner_name;
  out->restitution = Blend(blend.restitution, own.restitution, other.restitution,
                           DescribeRestitution(own.restitution, other.restitution, me, them));
  out->friction = Blend(blend.friction, own.friction, other.friction,
                        DescribeFriction(own.friction, other.friction, me, them));
  out->stiffness = Blend(blend.stiffness, own.stiffness, other.stiffness,
                         DescribeLayer("k", own.stiffness, other.stiffness, me, them));
  out->damping = Blend(blend.damping, own.damping, other.damping,
                       DescribeLayer("c", own.damping, other.damping, me, them));
  out->rolling = Blend(blend.rolling, own.rolling_friction, other.rolling_friction,
                       DescribeResistance(own.rolling_friction, other.rolling_friction, me, them));
  out->spinning =
      Blend(blend.spinning, own.spinning_friction, other.spinning_friction,
            DescribeResistance(own.spinning_friction, other.spinning_friction, me, them));
}

PairReadout ReadPair(const Simulator& sim, const ContactPair& pair, int body_id, int partner) {
  PairReadout out;
  out.partner = partner;
  out.partner_name = BodyLabel(sim.world(), partner);
  ReadSurface(sim, body_id, partner, &out);
  out.contact_count = static_cast<int>(pair.contacts.size());
  out.max_depth = pair.max_depth;
  out.padding_sum = pair.tolerance;
  ReadNormalForce(sim, body_id, partner, &out);
  ReadLaw(sim, pair, &out);
  return out;
}

}  // namespace

std::vector<PairReadout> ReadContacts(const Simulator& sim, int body_id) {
  std::vector<PairReadout> readouts;
  for (const ContactPair& pair : sim.contact_pairs()) {
    const int partner = PartnerIn(pair, body_id);
    if (partner >= 0) readouts.push_back(ReadPair(sim, pair, body_id, partner));
  }
  return readouts;
}

std::string DescribeRestitution(double own, double partner, const std::string& own_name,
                                const std::string& partner_name) {
  return "mean of " + Named(own, own_name) + " and " + Named(partner, partner_name);
}

// BlendSurfaces: 2 × the series combination, whose first infinite side drops out
std::string DescribeFriction(double own, double partner, const std::string& own_name,
                             const std::string& partner_name) {
  if (std::isinf(own) && std::isinf(partner)) return "both sides infinite: inf";
  if (std::isinf(own))
    return "one side infinite (" + own_name + "): twice " + Named(partner, partner_name);
  if (std::isinf(partner)) {
    return "one side infinite (" + partner_name + "): twice " + Named(own, own_name);
  }
  if (own == 0.0 || partner == 0.0) {
    return "one side frictionless (" + (own == 0.0 ? own_name : partner_name) + "): 0";
  }
  return "harmonic mean of " + Named(own, own_name) + " and " + Named(partner, partner_name);
}

std::string DescribeResistance(double own, double partner, const std::string& own_name,
                               const std::string& partner_name) {
  if (own == 0.0 && partner == 0.0) return "off on both sides: 0";
  if (own == 0.0 || partner == 0.0) {
    return "off on one side (" + (own == 0.0 ? own_name : partner_name) + "): 0";
  }
  return "harmonic mean of " + Named(own, own_name) + " and " + Named(partner, partner_name);
}

std::string DescribeLayer(const char* symbol, double own, double partner,
                          const std::string& own_name, const std::string& partner_name) {
  const std::string s = symbol;
  if (std::isinf(own) && std::isinf(partner)) return "both sides rigid: inf (hard contact)";
  if (std::isinf(own))
    return "one side rigid (" + own_name + "): the other side's " + Named(partner, partner_name);
  if (std::isinf(partner)) {
    return "one side rigid (" + partner_name + "): the other side's " + Named(own, own_name);
  }
  if (own == 0.0 || partner == 0.0) {
    return "one side " + s + " = 0 (" + (own == 0.0 ? own_name : partner_name) + "): 0";
  }
  return "series: 1/(1/" + s + "a + 1/" + s + "b) of " + Named(own, own_name) + " and " +
         Named(partner, partner_name);
}

std::string BodyLabel(const WorldDesc& world, int id) {
  const WorldId where = world.Resolve(id);
  switch (where.kind) {
    case WorldId::Kind::kTerrain:
      return ElementName(world.terrains[where.index].name, "terrain", where.index);
    case WorldId::Kind::kRigidObject:
      return ElementName(world.objects[where.index].name, "object", where.index);
    case WorldId::Kind::kRobot:
      return ElementName(world.robots[where.index].name, "robot", where.index);
    case WorldId::Kind::kRobotLink: {
      const std::string& name = world.robots[where.index].links[where.link].name;
      if (!name.empty()) return name;
      return "link " + std::to_string(where.link) + " of robot " + std::to_string(where.index);
    }
    case WorldId::Kind::kInvalid:
      break;
  }
  return "id " + std::to_string(id);
}

std::string BodiesText(const WorldDesc& world, const std::vector<int>& ids) {
  constexpr size_t kNamed = 3;
  std::string text;
  for (size_t i = 0; i < ids.size() && i < kNamed; ++i) {
    if (i > 0) text += i + 1 == ids.size() ? " and " : ", ";
    // (appended piece by piece: GCC 12 at -O3 warns falsely on "..." + std::string&&)
    text += '\'';
    text += BodyLabel(world, ids[i]);
    text += "' (id ";
    text += std::to_string(ids[i]);
    text += ')';
  }
  if (ids.size() > kNamed) text += " and " + std::to_string(ids.size() - kNamed) + " more";
  return text;
}

}  // namespace lamina::core
