// SPDX-License-Identifier: MIT
// `lamina-headless stress`: the stress suite (core/accuracy/stress_case.h; docs/stress.md) — every
// case run and judged stable, flagged (and recovered) or failed, printed as a table and written
// as JSON; the exit code is 1 when a case failed.
#pragma once

#include "app/headless_render_commands.h"

namespace lamina::app {

Subcommand AddStressCommand(CLI::App& app);

}  // namespace lamina::app
