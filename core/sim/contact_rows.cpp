// SPDX-License-Identifier: MIT
#include "core/sim/contact_rows.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

namespace {

// the normal row's softness: the contact's share of the pair's spring and damper, or a hard row
void SetNormalRow(const Contact& contact, const PairLaw& law, double normal_speed, double step,
                  const RowSettings& settings, ContactRow* row) {
  const BlendedSurface& surface = law.surface;
  if (law.soft.soft) {
    // force share = k·d_max·share = k_i·d_i
    const double share = PressureWeight(contact, law.floor) / law.weight_sum;
    const SoftContactParams soft = SoftContact(surface.stiffness * law.max_depth * share /
                                                   ContactWeightDepth(contact.depth, law.tolerance),
                                               surface.damping * share, step);
    row->erp = soft.erp;
    row->cfm = soft.cfm;
    row->core = contact.depth >= law.tolerance;
    return;
  }
  // a hard contact bounces at an impact, and otherwise corrects its overlap gently
  row->bounce = surface.restitution > 0.0;
  row->restitution = surface.restitution;
  row->bounce_velocity = settings.bounce_velocity_threshold;
  const bool bouncing = row->bounce && normal_speed < -settings.bounce_velocity_threshold;
  row->erp = bouncing ? 0.0 : HardContactErp(contact.depth, step, settings);
  row->cfm = std::min(settings.cfm, kHardContactCfm);
  if (bouncing && law.inverse_mass > 0.0) {
    row->cfm = std::min(row->cfm, kBounceRegularization * step * law.inverse_mass);
  }
}

// The first friction direction t1 whose second axis n × t1 is the rolling axis: ODE bounds the
// rolling torque about each friction axis separately, so only when one axis carries the rolling
// is the resistance ρ N in every direction (at 45° to the axes both would: √2 ρ N). Zero when
// rolling friction is off.
Vec3 RollingDirection(const Vec3& relative_angular, const Vec3& normal, double rolling) {
  if (!(rolling > 0.0)) return Vec3::Zero();
  const Vec3 axis = relative_angular - relative_angular.dot(normal) * normal;
  return axis.cross(normal);  // |axis × n| = |axis|, the rolling rate
}

// Whether the rolling takes the friction axes: it rolls, and it does not slide or its rolling
// friction dissipates more than its Coulomb friction (ρ |ω_t| > μ |v_t|). A ball rolling without
// slipping rolls; one that skids along its rolling direction has the same axes either way.
bool RollingTakesTheAxes(const Vec3& rolling, const Vec3& sliding, const ContactRow& row) {
  if (!(rolling.norm() > kRollingRateThreshold)) return false;
  const double slide = sliding.norm();
  return !(slide > kSlidingSpeedThreshold) || row.rolling * rolling.norm() > row.mu * slide;
}

// the friction directions and the anchor's correction along them
void SetFrictionRows(const Contact& contact, const Vec3& relative, double normal_speed,
                     const Vec3& anchor_velocity, const Vec3& relative_angular, ContactRow* row) {
  const Vec3 sliding = relative - normal_speed * contact.normal - anchor_velocity;
  const Vec3 rolling = RollingDirection(relative_angular, contact.normal, row->rolling);
  Vec3 t1 = Vec3::Zero(), t2 = Vec3::Zero();
  const bool rolls = RollingTakesTheAxes(rolling, sliding, *row);
  if (rolls || sliding.norm() > kSlidingSpeedThreshold) {
    t1 = rolls ? rolling.normalized() : sliding.normalized();
    t2 = contact.normal.cross(t1);  // as ODE makes it
    row->has_direction = true;
    row->fdir1 = t1;
  } else if (!anchor_velocity.isZero(0.0)) {
    dVector3 n = {contact.normal.x(), contact.normal.y(), contact.normal.z()}, p1, p2;
    dPlaneSpace(n, p1, p2);  // ODE's own friction axes
    t1 = Vec3(p1[0], p1[1], p1[2]);
    t2 = Vec3(p2[0], p2[1], p2[2]);
  }
  if (anchor_velocity.isZero(0.0)) return;
  // ODE's friction rows ask (v_a - v_b)·t_i = motion_i
  row->has_motion = true;
  row->motion1 = anchor_velocity.dot(t1);
  row->motion2 = anchor_velocity.dot(t2);
}

// ODE's rolling rows: about t1 and t2 bounded by rolling · N, about the normal by spinning · N
// (dContactApprox1 includes dContactApprox1_N, which makes the bounds proportional to N); an
// axis that is off is -1, which ODE clamps to 0 and gives no row
void SetRollingRows(const ContactRow& row, dSurfaceParameters* surface) {
  if (!(row.rolling > 0.0) && !(row.spinning > 0.0)) return;
  surface->mode |= dContactRolling | dContactAxisDep;
  surface->mu2 = surface->mu;
  surface->rho = row.rolling > 0.0 ? row.rolling : -1.0;
  surface->rho2 = surface->rho;
  surface->rhoN = row.spinning > 0.0 ? row.spinning : -1.0;
}

}  // namespace

double ContactWeightDepth(double depth, double tolerance) {
  return std::max(depth, 1e-6 * tolerance + 1e-12);
}

double HardContactErp(double depth, double step, const RowSettings& settings) {
  if (depth <= 0.0) return settings.erp;
  return std::min(settings.erp, settings.max_correction_speed * step / depth);
}

PairLaw MakePairLaw(const ContactPair& pair, const BlendedSurface& surface, double step) {
  PairLaw law;
  law.surface = surface;
  law.tolerance = pair.tolerance;
  law.floor = ContactWeightDepth(0.0, pair.tolerance);
  for (const Contact& contact : pair.contacts) {
    law.weight_sum += PressureWeight(contact, law.floor);
    law.max_depth = std::max(law.max_depth, ContactWeightDepth(contact.depth, pair.tolerance));
  }
  law.soft = SoftContact(surface.stiffness, surface.damping, step);
  law.pushes = !law.soft.soft || std::isfinite(law.soft.cfm);
  return law;
}

ContactRow MakeContactRow(const Contact& contact, const PairLaw& law, const Vec3& relative_velocity,
                          const Vec3& anchor_velocity, double step, const RowSettings& settings,
                          const Vec3& relative_angular_velocity) {
  ContactRow row;
  row.mu = law.surface.friction;
  row.rolling = law.surface.rolling;
  row.spinning = law.surface.spinning;
  const double normal_speed = relative_velocity.dot(contact.normal);
  SetNormalRow(contact, law, normal_speed, step, settings, &row);
  SetFrictionRows(contact, relative_velocity, normal_speed, anchor_velocity,
                  relative_angular_velocity, &row);
  if (row.core) {
    row.core_depth = contact.depth - law.tolerance;
    row.core_erp = HardContactErp(row.core_depth, step, settings);
    row.core_cfm = std::min(settings.cfm, kHardContactCfm);
  }
  return row;
}

dContact ToOdeContact(const ContactRow& row, const Contact& contact, bool core) {
  dContact joint{};
  joint.surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
  joint.surface.mu = std::isinf(row.mu) ? dInfinity : row.mu;
  joint.surface.soft_erp = core ? row.core_erp : row.erp;
  joint.surface.soft_cfm = core ? row.core_cfm : row.cfm;
  if (row.bounce && !core) {
    joint.surface.mode |= dContactBounce;
    joint.surface.bounce = row.restitution;
    joint.surface.bounce_vel = row.bounce_velocity;
  }
  if (row.has_direction) {
    joint.surface.mode |= dContactFDir1;
    joint.fdir1[0] = row.fdir1.x();
    joint.fdir1[1] = row.fdir1.y();
    joint.fdir1[2] = row.fdir1.z();
  }
  if (row.has_motion) {
    joint.surface.mode |= dContactMotion1 | dContactMotion2;
    joint.surface.motion1 = row.motion1;
    joint.surface.motion2 = row.motion2;
  }
  SetRollingRows(row, &joint.surface);
  const Vec3& p = contact.position;
  joint.geom.pos[0] = p.x();
  joint.geom.pos[1] = p.y();
  joint.geom.pos[2] = p.z();
  joint.geom.normal[0] = contact.normal.x();
  joint.geom.normal[1] = contact.normal.y();
  joint.geom.normal[2] = contact.normal.z();
  joint.geom.depth = core ? row.core_depth : contact.depth;
  return joint;
}

}  // namespace lamina::core
