// SPDX-License-Identifier: MIT
// A scalar piecewise polynomial of degree <= 3 over time: the per-DOF representation of queued
// and loaded motions. Outside its range it holds the end values with zero derivatives.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace lamina::core {

/// One piece: p(t) = c0 + c1 (t - start) + c2 (t - start)^2 + c3 (t - start)^3 on [start, end].
/// A piece with start == end is a jump: it takes effect at `start` (evaluation is
/// right-continuous) and its c1 is the velocity that continues from it.
struct PolynomialPiece {
  double start = 0;  ///< s
  double end = 0;    ///< s, >= start
  std::array<double, 4> coefficients{};

  double Duration() const { return end - start; }
  double Value(double t) const;
  double Derivative(double t) const;
  double SecondDerivative(double t) const;

  /// The constant `value` on [start, end].
  static PolynomialPiece Constant(double start, double end, double value);
  /// The cubic Hermite piece from (x0, v0) at `start` to (x1, v1) at `end` (a jump to (x1, v1)
  /// when end == start).
  static PolynomialPiece Hermite(double start, double end, double x0, double v0, double x1,
                                 double v1);
  /// The straight line from x0 at `start` to x1 at `end` (a jump to x1 when end == start).
  static PolynomialPiece Linear(double start, double end, double x0, double x1);
};

/// Pieces joined end to start. Evaluation before the first piece holds its start value, after
/// the last piece holds its end value, both with zero derivatives. At a knot the later piece
/// wins. Lookups are O(log n) and never allocate.
class PiecewisePolynomial {
 public:
  bool empty() const { return pieces_.empty(); }
  std::size_t piece_count() const { return pieces_.size(); }
  const std::vector<PolynomialPiece>& pieces() const { return pieces_; }
  /// s; 0 when empty.
  double StartTime() const;
  double EndTime() const;

  double Eval(double t) const;
  double Deriv(double t) const;
  double Accel(double t) const;
  /// Value and derivative at EndTime() as the last piece gives them (the derivative is the one
  /// a following piece continues from; 0 when empty).
  double EndValue() const;
  double EndDerivative() const;

  void Clear() { pieces_.clear(); }
  /// Appends `piece`; its start is moved to EndTime() when they differ by rounding. Returns false
  /// (and appends nothing) when the piece starts before EndTime() - 1e-9 or after it + 1e-9, or
  /// has end < start.
  bool Append(const PolynomialPiece& piece);
  /// Removes the pieces that end before `t` (at least one piece is always kept).
  void TrimFront(double t);
  /// Removes everything after `t`: pieces starting after t are dropped and the piece containing
  /// t ends at t. Nothing happens when t >= EndTime().
  void CutAfter(double t);
  /// Adds `offset` to every piece's start and end time.
  void Shift(double offset);

 private:
  // index of the piece that evaluates time t (the last piece starting at or before t, clamped)
  std::size_t PieceAt(double t) const;

  std::vector<PolynomialPiece> pieces_;
};

}  // namespace lamina::core
