// SPDX-License-Identifier: MIT
// A Monte-Carlo batch described in JSON (docs/batch.md), read and checked before any run:
//
//   {
//     "world": "control/world1.xml",          path relative to the spec file
//     "duration": 5, "simDt": 0.01,           s (simDt: the outer step, default 0.01)
//     "N": 100, "seed": 1,                    runs and the seed of their generators
//     "samplers": {"robots[0].config[0]": {"uniform": [-3.14159, 3.14159]}},
//     "set": {"robots[0].drivers[0].kP": 20}, fixed values on the description
//     "args": {"target": {"uniform": [-0.5, 0.5]}},
//     "setup": [{"robot": 0, "kP": [20], "kI": [8], "kD": [5], "pid": "args.target"}],
//     "terminate": [{"time": 4}, {"path": "robots[0].config[0]", "above": 7}, {"unstable": true}],
//     "return": ["robots[0].actualConfig"],    default: Klamp't's doSim items
//     "trace": {"rate": 0.1}                   items every 0.1 s (true: every simDt)
//   }
//
// Samplers: a number or an array (fixed), {"uniform": [lo, hi]}, {"normal": [mean, std]} (lo,
// hi, mean and std numbers or arrays of per-component values), {"choice": [v, ...]}, {"list":
// [v, ...]} (run i takes element i). Samplers draw in the spec's order, initial conditions
// first, then args. A set-up command takes a vector as numbers or as "args.NAME".
//
// Every error names the spec file and the JSON key
// (`seed1.json: samplers["robots[0].config[0]"]: uniform needs [lo, hi]`); path errors are the
// access paths' own (with suggestions); values are checked by the parameter table (a uniform
// range whose end the table refuses is refused here, not in every run).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/batch/batch_output.h"
#include "core/batch/batch_sim.h"
#include "core/model/world_desc.h"

namespace lamina::core {

struct BatchSpec {
  std::string file;        ///< as given
  std::string world_file;  ///< resolved against the spec's folder
  WorldDesc world;         ///< loaded, with `set` and the gains of `setup` applied
  RunPlan plan;
  MonteCarloSamplers samplers;
  int runs = 1;
  std::uint64_t seed = 0;
  std::vector<ColumnGroup> sampled;  ///< the samplers' columns, in drawing order
  std::vector<ColumnGroup> items;    ///< the return items' columns
  std::string hash;                  ///< of the spec (as parsed) and the world file's bytes

  /// The identity written into results.
  BatchMeta Meta() const;
};

/// Reads and checks the spec file `path`; nullopt with one message in `error`.
std::optional<BatchSpec> LoadBatchSpec(const std::string& path, std::string* error);
/// The same from text (`path` names it in messages and anchors relative paths).
std::optional<BatchSpec> ParseBatchSpec(const std::string& text, const std::string& path,
                                        std::string* error);

}  // namespace lamina::core
