// SPDX-License-Identifier: MIT
#include "core/sim/ode_contact_rows.h"

#include <algorithm>
#include <cmath>

#include <ode/ode.h>

#include "core/sim/ode_conversions.h"

namespace lamina::core {

namespace {

// (the halves are assigned one by one: Eigen's comma initializer cost about 100 instructions a
// row here, 6 % of the instructions of a 10-box stack's step, though no measurable CPU time)
Vec6 Motion(dBodyID body) {
  Vec6 v;
  v.head<3>() = ToVec3(dBodyGetLinearVel(body));
  v.tail<3>() = ToVec3(dBodyGetAngularVel(body));
  return v;
}

// the Jacobian entry of a row along `axis` at `arm` (contact point less the body's position)
Vec6 Linear(const Vec3& axis, const Vec3& arm) {
  Vec6 j;
  j.head<3>() = axis;
  j.tail<3>() = arm.cross(axis);
  return j;
}

Vec6 Angular(const Vec3& axis) {
  Vec6 j;
  j.head<3>().setZero();
  j.tail<3>() = axis;
  return j;
}

// what the two sides of every row share
struct RowContext {
  dBodyID a, b;
  int ia, ib;
  Vec3 arm_a, arm_b;
  double world_cfm;
};

// a row on both bodies; a kinematic body (a body outside the island) moves the right-hand side
NewtonRow MakeRow(const RowContext& c, const Vec6& ja, const Vec6& jb, double rhs, double cfm) {
  NewtonRow row;
  row.a = c.ia;
  row.b = c.ib;
  row.ja = ja;
  row.jb = c.b != nullptr ? jb : Vec6::Zero();
  row.rhs = rhs;
  row.cfm = cfm;
  if (c.ia < 0) row.rhs -= ja.dot(Motion(c.a));
  if (c.b != nullptr && c.ib < 0) row.rhs -= row.jb.dot(Motion(c.b));
  return row;
}

// getInfo2's normal row: ERP pushout capped by the world's correcting velocity, then bounce
NewtonRow NormalRow(const dContact& contact, const RowContext& c, const Vec3& normal,
                    dWorldID world, double step) {
  const dSurfaceParameters& s = contact.surface;
  const double erp = (s.mode & dContactSoftERP) != 0 ? s.soft_erp : dWorldGetERP(world);
  const double depth = std::max(contact.geom.depth - dWorldGetContactSurfaceLayer(world), 0.0);
  const double motion = (s.mode & dContactMotionN) != 0 ? s.motionN : 0.0;
  const double pushout = erp * depth / step + motion;
  double rhs = std::min(pushout, static_cast<double>(dWorldGetContactMaxCorrectingVel(world)));
  const Vec6 ja = Linear(normal, c.arm_a);
  const Vec6 jb = Linear(-normal, c.arm_b);
  if ((s.mode & dContactBounce) != 0 && s.bounce_vel >= 0) {
    double outgoing = ja.dot(Motion(c.a));
    if (c.b != nullptr) outgoing += jb.dot(Motion(c.b));
    const double incoming = motion - outgoing;
    if (incoming > s.bounce_vel) rhs = std::max(rhs, s.bounce * incoming + motion);
  }
  const double cfm = (s.mode & dContactSoftCFM) != 0 ? s.soft_cfm : c.world_cfm;
  NewtonRow row = MakeRow(c, ja, jb, rhs, cfm);
  row.lo = 0.0;
  row.hi = kInf;
  return row;
}

void Bound(NewtonRow* row, double coefficient, bool proportional, int normal) {
  row->lo = -coefficient;
  row->hi = coefficient;
  row->normal = proportional ? normal : -1;
}

// getInfo2's friction rows (ODE clamps a negative coefficient to 0: no row)
void FrictionRows(const dContact& contact, const RowContext& c, const Vec3& t1, const Vec3& t2,
                  int normal, std::vector<NewtonRow>* rows) {
  const dSurfaceParameters& s = contact.surface;
  const double mu = std::max(static_cast<double>(s.mu), 0.0);
  const double mu2 = (s.mode & dContactMu2) != 0 ? std::max(static_cast<double>(s.mu2), 0.0) : mu;
  const double coefficient[2] = {mu, mu2};
  const Vec3 axes[2] = {t1, t2};
  const bool has_motion[2] = {(s.mode & dContactMotion1) != 0, (s.mode & dContactMotion2) != 0};
  const double motion[2] = {s.motion1, s.motion2};
  const bool has_slip[2] = {(s.mode & dContactSlip1) != 0, (s.mode & dContactSlip2) != 0};
  const double slip[2] = {s.slip1, s.slip2};
  const int approx[2] = {dContactApprox1_1, dContactApprox1_2};
  for (int k = 0; k < 2; ++k) {
    if (coefficient[k] <= 0.0) continue;
    NewtonRow row = MakeRow(c, Linear(axes[k], c.arm_a), Linear(-axes[k], c.arm_b),
                            has_motion[k] ? motion[k] : 0.0, has_slip[k] ? slip[k] : c.world_cfm);
    Bound(&row, coefficient[k], (s.mode & approx[k]) != 0, normal);
    rows->push_back(row);
  }
}

// getInfo2's rolling and spinning rows: angular, about t1, t2 and the normal
void RollingRows(const dContact& contact, const RowContext& c, const Vec3 axes[3], int normal,
                 std::vector<NewtonRow>* rows) {
  const dSurfaceParameters& s = contact.surface;
  if ((s.mode & dContactRolling) == 0) return;
  const bool separate = (s.mode & dContactAxisDep) != 0;
  const double rho[3] = {s.rho, separate ? s.rho2 : s.rho, separate ? s.rhoN : s.rho};
  const int approx[3] = {dContactApprox1_1, dContactApprox1_2, dContactApprox1_N};
  for (int k = 0; k < 3; ++k) {
    if (!(rho[k] > 0.0)) continue;
    NewtonRow row = MakeRow(c, Angular(axes[k]), Angular(-axes[k]), 0.0, c.world_cfm);
    Bound(&row, rho[k], (s.mode & approx[k]) != 0, normal);
    rows->push_back(row);
  }
}

}  // namespace

bool ContactJointRows(const dContact& contact, dBodyID a, dBodyID b, int ia, int ib, dWorldID world,
                      double step, std::vector<NewtonRow>* rows) {
  Vec3 normal = ToVec3(contact.geom.normal);
  const bool swapped = a == nullptr;  // dJointAttach makes the body the first, reversed
  if (swapped) {
    std::swap(a, b);
    std::swap(ia, ib);
    normal = -normal;
  }
  const Vec3 point = ToVec3(contact.geom.pos);
  const RowContext c{a,
                     b,
                     ia,
                     ib,
                     point - ToVec3(dBodyGetPosition(a)),
                     b != nullptr ? Vec3(point - ToVec3(dBodyGetPosition(b))) : Vec3::Zero(),
                     dWorldGetCFM(world)};
  const int normal_index = static_cast<int>(rows->size());
  rows->push_back(NormalRow(contact, c, normal, world, step));
  Vec3 axes[3];
  if ((contact.surface.mode & dContactFDir1) != 0) {
    axes[0] = ToVec3(contact.fdir1);
    axes[1] = normal.cross(axes[0]);
  } else {
    dVector3 n = {normal.x(), normal.y(), normal.z(), 0.0}, p, q;
    dPlaneSpace(n, p, q);
    axes[0] = ToVec3(p);
    axes[1] = ToVec3(q);
  }
  axes[2] = normal;
  FrictionRows(contact, c, axes[0], axes[1], normal_index, rows);
  RollingRows(contact, c, axes, normal_index, rows);
  return swapped;
}

}  // namespace lamina::core
