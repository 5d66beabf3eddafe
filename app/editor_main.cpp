// SPDX-License-Identifier: MIT
// lamina: the desktop editor. Argument parsing and wiring only. This first version opens the
// window and shows what was loaded; rendering and the editing panels come next.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>
#include <imgui.h>

#include "core/io/world_file.h"
#include "core/model/world_summary.h"
#include "ui/platform/glfw_window.h"
#include "ui/platform/image_file.h"

namespace {

using lamina::core::WorldDesc;

void DrawWorldPanel(const WorldDesc& world, const lamina::core::Diagnostics& diagnostics) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(460, 220), ImGuiCond_FirstUseEver);
  ImGui::Begin("World");
  ImGui::Text("%s", world.name.c_str());
  ImGui::Separator();
  ImGui::Text("%zu terrains, %zu objects, %zu robots", world.terrains.size(), world.objects.size(),
              world.robots.size());
  for (const auto& robot : world.robots) {
    ImGui::BulletText("robot '%s': %d links, %.3f kg", robot.name.c_str(), robot.dof(),
                      robot.TotalMass());
  }
  if (!diagnostics.entries().empty()) {
    ImGui::Separator();
    ImGui::TextWrapped("%s", diagnostics.FormatAll().c_str());
  }
  ImGui::End();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lamina: the Lamina world editor"};
  std::string world_path = LAMINA_DEFAULT_WORLD;
  int frames = 0;
  std::string screenshot;
  app.add_option("world", world_path, "world file to open")->capture_default_str();
  app.add_option("--frames", frames, "quit after this many frames (0 = run until closed)");
  app.add_option("--screenshot", screenshot, "write the last frame to this PNG before quitting");
  CLI11_PARSE(app, argc, argv);

  lamina::core::Diagnostics diagnostics;
  lamina::core::MeshCache meshes;
  lamina::core::LoadContext context{diagnostics, meshes};
  WorldDesc world;
  lamina::core::LoadWorldFile(world_path, context, &world);
  std::cerr << diagnostics.FormatAll();

  lamina::ui::GlfwWindow window;
  std::string error;
  if (!window.Open("Lamina - " + world.name, 1280, 720, &error)) {
    std::cerr << "lamina: cannot open a window: " << error << "\n";
    return 1;
  }
  for (int frame = 0; !window.ShouldClose() && (frames == 0 || frame < frames); ++frame) {
    window.BeginFrame();
    DrawWorldPanel(world, diagnostics);
    window.EndFrame(0.18f, 0.20f, 0.24f);
    if (!screenshot.empty() && frame + 1 == frames) {
      int width = 0, height = 0;
      const auto pixels = window.ReadPixels(&width, &height);
      if (!lamina::ui::WritePngBottomUp(screenshot, width, height, pixels)) {
        std::cerr << "lamina: cannot write " << screenshot << "\n";
        return 1;
      }
    }
    window.Swap();
  }
  return diagnostics.HasErrors() ? 1 : 0;
}
