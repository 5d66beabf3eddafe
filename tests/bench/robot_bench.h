// SPDX-License-Identifier: MIT
// Benchmarks of Klamp't's robot example world athlete_fractal_1.xml with both ODE solvers.
#pragma once

namespace lamina::bench {

/// Registers Robot/athlete_fractal_1/<solver>.
void RegisterRobotBenchmarks();
/// Registers ErrorMeter/<world>: the live accuracy meter's cost (error_meter_bench.cpp).
void RegisterErrorMeterBenchmarks();

}  // namespace lamina::bench
