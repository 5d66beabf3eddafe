// SPDX-License-Identifier: MIT
#include "core/sim/ode_joint_rows.h"

#include <cmath>

#include <ode/ode.h>

#include "core/sim/ode_conversions.h"

namespace lamina::core {

namespace {

// what the rows of one joint share
struct JointContext {
  int ia, ib;
  bool has_b;      ///< the second body is a body (not the world)
  double cfm;      ///< the world's
  bool tree_rows;  ///< JointRows' `tree_rows`
};

// (the halves assigned one by one: Eigen's comma initializer cost about 100 instructions a row,
// as in ode_contact_rows.cpp; 3.3 % of the instructions of ATHLETE's step)
Vec6 Stack(const Vec3& linear, const Vec3& angular) {
  Vec6 j;
  j.head<3>() = linear;
  j.tail<3>() = angular;
  return j;
}

void AddRow(const JointContext& c, const Vec6& ja, const Vec6& jb, double rhs, double cfm,
            double lo, double hi, std::vector<NewtonRow>* rows) {
  NewtonRow row;
  row.a = c.ia;
  row.b = c.has_b ? c.ib : -1;
  row.ja = ja;
  row.jb = c.has_b ? jb : Vec6::Zero();
  row.rhs = rhs;
  row.cfm = cfm;
  row.lo = lo;
  row.hi = hi;
  rows->push_back(row);
}

// an angular row along `axis`: w_a·axis − w_b·axis
void AngularRow(const JointContext& c, const Vec3& axis, double rhs, double cfm, double lo,
                double hi, std::vector<NewtonRow>* rows) {
  AddRow(c, Stack(Vec3::Zero(), axis), Stack(Vec3::Zero(), -axis), rhs, cfm, lo, hi, rows);
}

// setBall (joint_internal.h): the anchor seen from both bodies meets; the right-hand side pulls
// the second body's anchor onto the first's at the world ERP
void BallRows(dJointID joint, const JointContext& c, double k, std::vector<NewtonRow>* rows) {
  dVector3 anchor1, anchor2;
  dJointGetHingeAnchor(joint, anchor1);
  dJointGetHingeAnchor2(joint, anchor2);
  const Vec3 arm1 = ToVec3(anchor1) - ToVec3(dBodyGetPosition(dJointGetBody(joint, 0)));
  dBodyID second = dJointGetBody(joint, 1);
  const Vec3 arm2 =
      second != nullptr ? Vec3(ToVec3(anchor2) - ToVec3(dBodyGetPosition(second))) : Vec3::Zero();
  const Vec3 error = ToVec3(anchor2) - ToVec3(anchor1);
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = Vec3::Unit(i);
    AddRow(c, Stack(e, arm1.cross(e)), Stack(-e, -arm2.cross(e)), k * error(i), c.cfm, -kInf, kInf,
           rows);
  }
}

// the law of addLimot's stop row for an unpowered joint whose coordinate (hinge angle, slider
// position) is `value`: pushes back at the stop ERP, one-sided unless both stops meet
struct StopLaw {
  double rhs, lo, hi;
};
StopLaw Stop(double value, double lo, double hi, double erp, double step) {
  const bool low = value <= lo;
  const double rhs = -erp / step * (low ? value - lo : value - hi);
  if (lo == hi) return {rhs, -kInf, kInf};
  return {rhs, low ? 0.0 : -kInf, low ? kInf : 0.0};
}

// the hinge's stop row, when getInfo1's test finds it at a stop
void HingeStopRow(dJointID joint, const JointContext& c, const Vec3& axis, double step,
                  std::vector<NewtonRow>* rows) {
  const double lo = dJointGetHingeParam(joint, dParamLoStop);
  const double hi = dJointGetHingeParam(joint, dParamHiStop);
  if (!((lo >= -M_PI || hi <= M_PI) && lo <= hi)) return;  // getInfo1's test
  const double angle = dJointGetHingeAngle(joint);
  if (angle > lo && angle < hi) return;
  const StopLaw law = Stop(angle, lo, hi, dJointGetHingeParam(joint, dParamStopERP), step);
  AngularRow(c, axis, law.rhs, dJointGetHingeParam(joint, dParamStopCFM), law.lo, law.hi, rows);
}

bool HingeRows(dJointID joint, const JointContext& c, const Vec3& axis2, double erp, double step,
               std::vector<NewtonRow>* rows) {
  if (dJointGetHingeParam(joint, dParamFMax) > 0.0 ||
      dJointGetHingeParam(joint, dParamBounce) > 0.0)
    return false;
  dVector3 axis1;
  dJointGetHingeAxis(joint, axis1);
  if (!c.tree_rows) {
    HingeStopRow(joint, c, ToVec3(axis1), step, rows);
    return true;
  }
  const double k = erp / step;
  BallRows(joint, c, k, rows);
  dVector3 p, q;
  dPlaneSpace(axis1, p, q);
  const Vec3 ax1 = ToVec3(axis1);
  dBodyID second = dJointGetBody(joint, 1);
  const Vec3 ax2 = second != nullptr ? Vec3(ToMat3(dBodyGetRotation(second)) * axis2) : axis2;
  const Vec3 misalignment = ax1.cross(ax2);
  AngularRow(c, ToVec3(p), k * misalignment.dot(ToVec3(p)), c.cfm, -kInf, kInf, rows);
  AngularRow(c, ToVec3(q), k * misalignment.dot(ToVec3(q)), c.cfm, -kInf, kInf, rows);
  HingeStopRow(joint, c, ax1, step, rows);
  return true;
}

// one row per powered axis, bounded by its fmax
bool AngularMotorRows(dJointID joint, const JointContext& c, std::vector<NewtonRow>* rows) {
  if (dJointGetAMotorMode(joint) != dAMotorUser) return false;
  const int axes = dJointGetAMotorNumAxes(joint);
  for (int i = 0; i < axes; ++i) {
    const int group = dParamGroup * i;
    if (std::isfinite(dJointGetAMotorParam(joint, dParamLoStop + group)) ||
        std::isfinite(dJointGetAMotorParam(joint, dParamHiStop + group)) ||
        (dJointGetAMotorParam(joint, dParamFMax + group) > 0.0 &&
         !(dJointGetAMotorParam(joint, dParamCFM + group) > 0.0))) {
      return false;  // stops, or a hard row (newton_solver.h: every row is soft)
    }
  }
  for (int i = 0; i < axes; ++i) {
    const int group = dParamGroup * i;
    const double fmax = dJointGetAMotorParam(joint, dParamFMax + group);
    if (!(fmax > 0.0)) continue;
    dVector3 axis;
    dJointGetAMotorAxis(joint, i, axis);
    AngularRow(c, ToVec3(axis), dJointGetAMotorParam(joint, dParamVel + group),
               dJointGetAMotorParam(joint, dParamCFM + group), -fmax, fmax, rows);
  }
  return true;
}

// ODE's quaternion (w, x, y, z)
Eigen::Quaterniond Quaternion(const double* q) {
  return {q[0], q[1], q[2], q[3]};
}

// setFixedOrientation (joint_internal.h): the bodies' angular velocities equal, the right-hand
// side turning the second body back to its rotation relative to the first at build
void FixedOrientationRows(dJointID joint, const JointContext& c, const JointFrame& frame, double k,
                          std::vector<NewtonRow>* rows) {
  dBodyID first = dJointGetBody(joint, 0), second = dJointGetBody(joint, 1);
  const Eigen::Quaterniond relative(frame.relative(0), frame.relative(1), frame.relative(2),
                                    frame.relative(3));
  const Eigen::Quaterniond q1 = Quaternion(dBodyGetQuaternion(first));
  const Eigen::Quaterniond error =
      second != nullptr
          ? Eigen::Quaterniond(q1.conjugate() * Quaternion(dBodyGetQuaternion(second))) *
                relative.conjugate()
          : Eigen::Quaterniond(q1.conjugate() * relative.conjugate());
  const Vec3 half_turn = error.w() < 0.0 ? Vec3(-error.vec()) : Vec3(error.vec());
  const Vec3 turn = ToMat3(dBodyGetRotation(first)) * half_turn;
  for (int i = 0; i < 3; ++i)
    AngularRow(c, Vec3::Unit(i), 2.0 * k * turn(i), c.cfm, -kInf, kInf, rows);
}

// half the line between the bodies' centres: a linear row between two bodies acts at its middle
// (addLimot's torque decoupling), so that it makes no couple
Vec3 HalfwayArm(dJointID joint) {
  dBodyID second = dJointGetBody(joint, 1);
  if (second == nullptr) return Vec3::Zero();
  return 0.5 *
         (ToVec3(dBodyGetPosition(second)) - ToVec3(dBodyGetPosition(dJointGetBody(joint, 0))));
}

// a linear row along `axis` through the middle of the bodies
void LinearRow(const JointContext& c, const Vec3& axis, const Vec3& halfway, double rhs, double cfm,
               double lo, double hi, std::vector<NewtonRow>* rows) {
  const Vec3 decoupling = halfway.cross(axis);
  AddRow(c, Stack(axis, decoupling), Stack(-axis, decoupling), rhs, cfm, lo, hi, rows);
}

// the slider's stop row (getInfo1 tests its stops whenever one is finite)
void SliderStopRow(dJointID joint, const JointContext& c, const Vec3& axis, double step,
                   std::vector<NewtonRow>* rows) {
  const double lo = dJointGetSliderParam(joint, dParamLoStop);
  const double hi = dJointGetSliderParam(joint, dParamHiStop);
  if (!((lo > -kInf || hi < kInf) && lo <= hi)) return;
  const double position = dJointGetSliderPosition(joint);
  if (position > lo && position < hi) return;
  const StopLaw law = Stop(position, lo, hi, dJointGetSliderParam(joint, dParamStopERP), step);
  LinearRow(c, axis, HalfwayArm(joint), law.rhs, dJointGetSliderParam(joint, dParamStopCFM), law.lo,
            law.hi, rows);
}

// three rows keeping the rotations, two keeping the first body's centre on the axis through the
// second body's offset point (with (ω1 + ω2)/2 for ω1), the stop row
bool SliderRows(dJointID joint, const JointContext& c, const JointFrame& frame, double erp,
                double step, std::vector<NewtonRow>* rows) {
  if (dJointGetSliderParam(joint, dParamFMax) > 0.0 ||
      dJointGetSliderParam(joint, dParamBounce) > 0.0) {
    return false;
  }
  dVector3 axis1;
  dJointGetSliderAxis(joint, axis1);
  if (!c.tree_rows) {
    SliderStopRow(joint, c, ToVec3(axis1), step, rows);
    return true;
  }
  const double k = erp / step;
  FixedOrientationRows(joint, c, frame, k, rows);
  dVector3 p, q;
  dPlaneSpace(axis1, p, q);
  const Vec3 position1 = ToVec3(dBodyGetPosition(dJointGetBody(joint, 0)));
  dBodyID second = dJointGetBody(joint, 1);
  Vec3 gap = frame.offset - position1;  // from the first body's centre to where it belongs
  Vec3 between = Vec3::Zero();
  if (second != nullptr) {
    between = ToVec3(dBodyGetPosition(second)) - position1;
    gap = between + ToMat3(dBodyGetRotation(second)) * frame.offset;
  }
  for (const Vec3& across : {ToVec3(p), ToVec3(q)}) {
    const Vec3 arm = 0.5 * between.cross(across);
    AddRow(c, Stack(across, arm), Stack(-across, arm), k * across.dot(gap), c.cfm, -kInf, kInf,
           rows);
  }
  SliderStopRow(joint, c, ToVec3(axis1), step, rows);
  return true;
}

// one row per powered axis, through the middle of the bodies, bounded by its fmax (ODE never
// tests a linear motor's stops)
bool LinearMotorRows(dJointID joint, const JointContext& c, const JointFrame& frame,
                     std::vector<NewtonRow>* rows) {
  const int axes = dJointGetLMotorNumAxes(joint);
  const Vec3 axis = ToMat3(dBodyGetRotation(dJointGetBody(joint, 0))) * frame.axis1;
  const Vec3 halfway = HalfwayArm(joint);
  for (int i = 0; i < axes; ++i) {
    const int group = dParamGroup * i;
    const double fmax = dJointGetLMotorParam(joint, dParamFMax + group);
    if (!(fmax > 0.0)) continue;
    const double cfm = dJointGetLMotorParam(joint, dParamCFM + group);
    if (!(cfm > 0.0)) return false;  // a hard row
    LinearRow(c, axis, halfway, dJointGetLMotorParam(joint, dParamVel + group), cfm, -fmax, fmax,
              rows);
  }
  return true;
}

}  // namespace

JointFrame OdeHingeFrame(dBodyID second, const Vec3& axis) {
  JointFrame frame;
  frame.axis2 = second != nullptr
                    ? Vec3(ToMat3(dBodyGetRotation(second)).transpose() * axis.normalized())
                    : axis;
  return frame;
}

JointFrame OdeSliderFrame(dBodyID first, dBodyID second, const Vec3& axis) {
  JointFrame frame;
  const double* q1 = dBodyGetQuaternion(first);
  const Eigen::Quaterniond first_turn(q1[0], q1[1], q1[2], q1[3]);
  Eigen::Quaterniond relative = first_turn.conjugate();
  const Vec3 position = ToVec3(dBodyGetPosition(first));
  frame.offset = position;
  if (second != nullptr) {
    const double* q2 = dBodyGetQuaternion(second);
    relative = first_turn.conjugate() * Eigen::Quaterniond(q2[0], q2[1], q2[2], q2[3]);
    frame.offset = ToMat3(dBodyGetRotation(second)).transpose() *
                   (position - ToVec3(dBodyGetPosition(second)));
  }
  frame.relative << relative.w(), relative.x(), relative.y(), relative.z();
  frame.axis1 = ToMat3(dBodyGetRotation(first)).transpose() * axis;
  return frame;
}

bool JointRows(dJointID joint, int ia, int ib, const JointFrame& frame, dWorldID world, double step,
               std::vector<NewtonRow>* rows, bool tree_rows) {
  const JointContext c{ia, ib, dJointGetBody(joint, 1) != nullptr, dWorldGetCFM(world), tree_rows};
  const size_t before = rows->size();
  bool known = false;
  switch (dJointGetType(joint)) {
    case dJointTypeHinge:
      known = HingeRows(joint, c, frame.axis2, dWorldGetERP(world), step, rows);
      break;
    case dJointTypeSlider:
      known = SliderRows(joint, c, frame, dWorldGetERP(world), step, rows);
      break;
    case dJointTypeAMotor:
      known = AngularMotorRows(joint, c, rows);
      break;
    case dJointTypeLMotor:
      known = LinearMotorRows(joint, c, frame, rows);
      break;
    default:
      break;
  }
  if (!known) rows->resize(before);
  return known;
}

}  // namespace lamina::core
