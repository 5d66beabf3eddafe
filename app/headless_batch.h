// SPDX-License-Identifier: MIT
// `lamina-headless batch SPEC.json` (Monte-Carlo batches on every core, shards) and
// `lamina-headless batch merge PART...` (docs/batch.md).
#pragma once

#include <CLI/CLI.hpp>

#include "app/headless_render_commands.h"

namespace lamina::app {

Subcommand AddBatchCommand(CLI::App& app);

}  // namespace lamina::app
