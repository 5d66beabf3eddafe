// SPDX-License-Identifier: MIT
// Helpers of the batch tests (tests/batch, tests/physics): specs, runs on a pool.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/batch/batch_output.h"
#include "core/batch/batch_sim.h"
#include "core/batch/batch_spec.h"
#include "tests/common/test_support.h"

namespace lamina::test {

/// A spec under worlds/ (e.g. "batch/spin_to_zero.json"), loaded (a failure fails the test).
inline core::BatchSpec LoadSpec(const std::string& relative) {
  std::string error;
  std::optional<core::BatchSpec> spec = core::LoadBatchSpec(WorldsPath(relative), &error);
  EXPECT_TRUE(spec.has_value()) << error;
  return spec ? *spec : core::BatchSpec{};
}

/// A spec in the scratch folder with `body` (JSON members), its world the seed example's
/// (worlds/klampt/control/world1.xml, absolute path).
inline std::optional<core::BatchSpec> ScratchSpec(const std::string& name, const std::string& body,
                                                  std::string* error) {
  const std::string text =
      "{\"world\": \"" + WorldsPath("klampt/control/world1.xml") + "\", " + body + "}";
  return core::ParseBatchSpec(text, ScratchDir() + "/" + name, error);
}

inline std::vector<int> AllRuns(const core::BatchSpec& spec) {
  return core::ShardIndices(spec.runs, core::Shard{});
}

/// The runs `indices` of `spec` on `threads` (0: every core).
inline core::BatchTable RunBatch(const core::BatchSpec& spec, const std::vector<int>& indices,
                                 int threads) {
  core::PoolOptions pool;
  pool.threads = threads;
  core::BatchTable table{spec.sampled, spec.items, {}};
  table.runs = core::MonteCarloSim(spec.world, spec.plan, spec.samplers, spec.seed, indices, pool);
  return table;
}

}  // namespace lamina::test
