// SPDX-License-Identifier: MIT
// `lamina-headless accuracy`: the accuracy suite (core/accuracy) swept over steps and solvers,
// written as CSV, JSON, SVG plots and Markdown (docs/accuracy.md through `make accuracy`).
#pragma once

#include "app/headless_render_commands.h"

namespace lamina::app {

Subcommand AddAccuracyCommand(CLI::App& app);

}  // namespace lamina::app
