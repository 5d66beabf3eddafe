// SPDX-License-Identifier: MIT
// Benchmarks of every Klamp't simulation test world with both ODE solvers, registered at run
// time because the worlds are found on disk.
#pragma once

namespace lamina::bench {

/// Registers World/<name>/<solver> for each worlds/klampt/simulation_test_worlds/*.xml.
void RegisterWorldBenchmarks();

}  // namespace lamina::bench
