// SPDX-License-Identifier: MIT
// lamina-headless: the command-line tool (no window). Argument parsing and wiring only.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "core/io/world_file.h"
#include "core/model/world_summary.h"

namespace {

using lamina::core::Diagnostics;
using lamina::core::LoadContext;
using lamina::core::MeshCache;
using lamina::core::WorldDesc;

// loads `path`, printing every diagnostic to stderr; false on any error
bool LoadWorldReporting(const std::string& path, WorldDesc* world) {
  Diagnostics diagnostics;
  MeshCache meshes;
  LoadContext context{diagnostics, meshes};
  const bool ok = lamina::core::LoadWorldFile(path, context, world);
  std::cerr << diagnostics.FormatAll();
  return ok && !diagnostics.HasErrors();
}

int RunInfo(const std::string& path, bool json) {
  WorldDesc world;
  if (!LoadWorldReporting(path, &world)) return 1;
  std::cout << (json ? lamina::core::WorldSummaryJson(world)
                     : lamina::core::WorldSummaryText(world));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lamina-headless: load, inspect, simulate and render Lamina/Klamp't worlds"};
  app.require_subcommand(1);

  std::string info_world;
  bool info_json = false;
  CLI::App* info = app.add_subcommand("info", "print what a world file holds");
  info->add_option("world", info_world, "world .xml, or a .rob/.urdf/.obj/.env/mesh file")
      ->required();
  info->add_flag("--json", info_json, "print JSON instead of text");

  CLI11_PARSE(app, argc, argv);
  if (info->parsed()) return RunInfo(info_world, info_json);
  return 2;
}
