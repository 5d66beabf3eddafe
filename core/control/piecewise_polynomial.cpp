// SPDX-License-Identifier: MIT
// Piecewise cubic polynomials (see piecewise_polynomial.h).
#include "core/control/piecewise_polynomial.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {
namespace {

// Appended pieces may start this far (s) from the current end and are snapped onto it.
constexpr double kJoinTolerance = 1e-9;

}  // namespace

double PolynomialPiece::Value(double t) const {
  const double u = t - start;
  const auto& c = coefficients;
  return c[0] + u * (c[1] + u * (c[2] + u * c[3]));
}

double PolynomialPiece::Derivative(double t) const {
  const double u = t - start;
  const auto& c = coefficients;
  return c[1] + u * (2 * c[2] + u * 3 * c[3]);
}

double PolynomialPiece::SecondDerivative(double t) const {
  const double u = t - start;
  return 2 * coefficients[2] + 6 * coefficients[3] * u;
}

PolynomialPiece PolynomialPiece::Constant(double start, double end, double value) {
  return {start, end, {value, 0, 0, 0}};
}

PolynomialPiece PolynomialPiece::Hermite(double start, double end, double x0, double v0, double x1,
                                         double v1) {
  const double h = end - start;
  if (h <= 0) return {start, start, {x1, v1, 0, 0}};
  const double dx = x1 - x0;
  const double c2 = (3 * dx / h - 2 * v0 - v1) / h;
  const double c3 = (v0 + v1 - 2 * dx / h) / (h * h);
  return {start, end, {x0, v0, c2, c3}};
}

PolynomialPiece PolynomialPiece::Linear(double start, double end, double x0, double x1) {
  const double h = end - start;
  if (h <= 0) return {start, start, {x1, 0, 0, 0}};
  return {start, end, {x0, (x1 - x0) / h, 0, 0}};
}

double PiecewisePolynomial::StartTime() const {
  return empty() ? 0.0 : pieces_.front().start;
}
double PiecewisePolynomial::EndTime() const {
  return empty() ? 0.0 : pieces_.back().end;
}

std::size_t PiecewisePolynomial::PieceAt(double t) const {
  const auto after = std::upper_bound(
      pieces_.begin(), pieces_.end(), t,
      [](double time, const PolynomialPiece& piece) { return time < piece.start; });
  if (after == pieces_.begin()) return 0;
  return static_cast<std::size_t>(after - pieces_.begin()) - 1;
}

double PiecewisePolynomial::Eval(double t) const {
  if (empty()) return 0.0;
  if (t <= pieces_.front().start) return pieces_.front().Value(pieces_.front().start);
  if (t >= pieces_.back().end) return EndValue();
  return pieces_[PieceAt(t)].Value(t);
}

double PiecewisePolynomial::Deriv(double t) const {
  if (empty() || t < pieces_.front().start || t > pieces_.back().end) return 0.0;
  return pieces_[PieceAt(t)].Derivative(t);
}

double PiecewisePolynomial::Accel(double t) const {
  if (empty() || t < pieces_.front().start || t > pieces_.back().end) return 0.0;
  return pieces_[PieceAt(t)].SecondDerivative(t);
}

double PiecewisePolynomial::EndValue() const {
  return empty() ? 0.0 : pieces_.back().Value(pieces_.back().end);
}

double PiecewisePolynomial::EndDerivative() const {
  return empty() ? 0.0 : pieces_.back().Derivative(pieces_.back().end);
}

bool PiecewisePolynomial::Append(const PolynomialPiece& piece) {
  if (!(piece.end >= piece.start)) return false;
  if (empty()) {
    pieces_.push_back(piece);
    return true;
  }
  const double end = EndTime();
  if (std::abs(piece.start - end) > kJoinTolerance) return false;
  PolynomialPiece joined = piece;
  joined.start = end;
  joined.end = std::max(end, piece.end);
  pieces_.push_back(joined);
  return true;
}

void PiecewisePolynomial::TrimFront(double t) {
  std::size_t first_kept = 0;
  while (first_kept + 1 < pieces_.size() && pieces_[first_kept].end < t) ++first_kept;
  pieces_.erase(pieces_.begin(), pieces_.begin() + static_cast<std::ptrdiff_t>(first_kept));
}

void PiecewisePolynomial::CutAfter(double t) {
  if (empty() || t >= EndTime()) return;
  if (t <= pieces_.front().start) {
    const PolynomialPiece first = pieces_.front();
    pieces_.assign(1, first);
    pieces_.front().end = first.start;
    return;
  }
  const std::size_t index = PieceAt(t);
  pieces_.resize(index + 1);
  pieces_.back().end = t;
}

void PiecewisePolynomial::Shift(double offset) {
  for (PolynomialPiece& piece : pieces_) {
    piece.start += offset;
    piece.end += offset;
  }
}

}  // namespace lamina::core
