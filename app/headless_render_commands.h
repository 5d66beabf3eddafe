// SPDX-License-Identifier: MIT
// The rendering subcommands of lamina-headless: `shot` (one PNG of a world at a time) and
// `record` (frames in simulation time, as PNGs or an .mp4 through ffmpeg).
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace lamina::app {

struct Subcommand {
  CLI::App* command = nullptr;
  std::function<int()> run;  ///< call when command->parsed(); returns the exit code
};

Subcommand AddShotCommand(CLI::App& app);
Subcommand AddRecordCommand(CLI::App& app);

}  // namespace lamina::app
