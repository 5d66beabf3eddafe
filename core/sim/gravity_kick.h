// SPDX-License-Identifier: MIT
// Gravity's kick when the step length changes. ODE's step is symplectic Euler: v += h·a, then
// x += h·v. Its velocity is a leapfrog's, half a step behind the positions (v after a step of h is
// the velocity at t − h/2 to first order), and its kicks sit between the steps. At a constant step
// each kick spans one step and the scheme is symmetric in time: a ball bounces back up the same
// positions it fell through. When the step changes from h₀ to h (adaptive stepping halves it at an
// impact and returns to the whole step after), the kick between them must span (h₀ + h)/2, half of
// each; taking just h instead moves the velocity by a·(h₀ − h)/2 with no time passing, and a ball
// at v = 9.9 m/s lost 0.15 % of its energy per bounce at 1 ms.
//
// Lamina scales gravity for the first step after a change by (h₀ + h)/(2h), so that its kick spans
// (h₀ + h)/2 (ODE and Klamp't kick g·h at every step). Every body feels gravity, and the solver
// turns the extra kick into the constrained motion (a resting box's contact takes it all, a rolling
// ball's share is its 5/7); the other forces (springs, servos, contacts) are solved in the step and
// keep their kick h. At a constant step the scale is exactly 1 and nothing changes.
// Units: s.
#pragma once

namespace lamina::core {

/// What gravity is scaled by in a step of `step` that follows an accepted step of `previous`:
/// (previous + step) / (2·step); 1 when there was no previous step (`previous` ≤ 0) or they are
/// equal.
double GravityKickScale(double previous, double step);

}  // namespace lamina::core
