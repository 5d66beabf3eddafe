// SPDX-License-Identifier: MIT
// Benchmarks of robots standing (athlete_fractal_1.xml, hrp2_plane.xml) with both ODE solvers.
#pragma once

namespace lamina::bench {

/// Registers Robot/athlete_fractal_1/<solver> and Robot/hrp2_plane/<solver>.
void RegisterRobotBenchmarks();
/// Registers ErrorMeter/<world>: the live accuracy meter's cost (error_meter_bench.cpp).
void RegisterErrorMeterBenchmarks();

}  // namespace lamina::bench
