// SPDX-License-Identifier: MIT
// The stress suite's report (stress_run.h): a table for the terminal, one JSON document with a
// record per case, and the Markdown table of docs/stress.md. Pure text out.
#pragma once

#include <string>
#include <vector>

#include "core/accuracy/stress_run.h"

namespace lamina::core {

/// One line per case: name, verdict (with "expected X" when it differs), status, rollbacks,
/// corrections, non-finite recoveries, smallest step, deepest overlap, CPU time, the case's
/// number; then each flagged or failed case's reason.
std::string StressTable(const std::vector<StressRecord>& records);
/// {"cases": [{name, world, solver, step, duration, verdict, expected, why, status, steps,
/// rollbacks, instability_corrections, nonfinite_recoveries, unreliable_steps, min_step,
/// max_penetration, cpu_s, metric: {text, unit, value}, probe: {error, note, metrics},
/// lost: [...], failure}], "failed": n}. Steps and lengths in s and m; non-finite numbers null.
std::string StressJson(const std::vector<StressRecord>& records);
/// The Markdown table of the cases (docs/stress.md).
std::string StressMarkdownTable(const std::vector<StressRecord>& records);
/// Cases that failed.
int FailedCount(const std::vector<StressRecord>& records);

}  // namespace lamina::core
