// SPDX-License-Identifier: MIT
#include "core/sim/row_relaxation.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {
namespace {

// M⁻¹ of one body: 1/m and the world inverse inertia
struct InverseMass {
  double mass = 0.0;
  Mat3 inertia = Mat3::Zero();
};

Vec6 InverseTimes(const InverseMass& inverse, const Vec6& w) {
  Vec6 out;
  out.head<3>() = inverse.mass * w.head<3>();
  out.tail<3>() = inverse.inertia * w.tail<3>();
  return out;
}

// a row's bounds with the forces as they are (a friction row's from its normal row's |λ|)
void RowBounds(const std::vector<NewtonRow>& rows, const std::vector<double>& force, size_t i,
               double* lo, double* hi) {
  const NewtonRow& row = rows[i];
  if (row.normal < 0) {
    *lo = row.lo;
    *hi = row.hi;
    return;
  }
  const double normal = std::abs(force[static_cast<size_t>(row.normal)]);
  *lo = FrictionBound(row.lo, normal);
  *hi = FrictionBound(row.hi, normal);
}

// v += h M⁻¹ Jᵀ Δλ on the row's bodies
void AddRowImpulse(const NewtonRow& row, const std::vector<InverseMass>& inverse, double impulse,
                   VecX* v) {
  if (row.a >= 0) v->segment<6>(6 * row.a) += impulse * InverseTimes(inverse[row.a], row.ja);
  if (row.b >= 0) v->segment<6>(6 * row.b) += impulse * InverseTimes(inverse[row.b], row.jb);
}

// h J M⁻¹ Jᵀ + cfm: how much the row's own law moves per newton of its force
double RowStiffness(const NewtonRow& row, const std::vector<InverseMass>& inverse, double step) {
  double sum = row.cfm;
  if (row.a >= 0) sum += step * row.ja.dot(InverseTimes(inverse[row.a], row.ja));
  if (row.b >= 0) sum += step * row.jb.dot(InverseTimes(inverse[row.b], row.jb));
  return sum;
}

}  // namespace

void RelaxRows(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
               double step, int sweeps, NewtonResult* result) {
  std::vector<InverseMass> inverse(bodies.size());
  VecX v(6 * static_cast<Eigen::Index>(bodies.size()));
  for (size_t k = 0; k < bodies.size(); ++k) {
    inverse[k].mass = 1.0 / bodies[k].mass;
    inverse[k].inertia = bodies[k].inertia.inverse();
    v.segment<6>(6 * static_cast<Eigen::Index>(k)) = bodies[k].free_velocity;
  }
  std::vector<double>& force = result->force;
  force.assign(rows.size(), 0.0);
  std::vector<double> stiffness(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) stiffness[i] = RowStiffness(rows[i], inverse, step);
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (size_t i = 0; i < rows.size(); ++i) {
      if (!(stiffness[i] > 0.0)) continue;
      const NewtonRow& row = rows[i];
      double lo = 0.0, hi = 0.0;
      RowBounds(rows, force, i, &lo, &hi);
      const double residual = row.rhs - RowVelocity(row, v) - row.cfm * force[i];
      const double next = std::clamp(force[i] + residual / stiffness[i], lo, hi);
      AddRowImpulse(row, inverse, step * (next - force[i]), &v);
      force[i] = next;
    }
  }
  result->velocity.resize(bodies.size());
  for (size_t k = 0; k < bodies.size(); ++k) {
    result->velocity[k] = v.segment<6>(6 * static_cast<Eigen::Index>(k));
  }
  result->iterations = sweeps;
  result->converged = false;
}

}  // namespace lamina::core
