// SPDX-License-Identifier: MIT
// World tree: the world's file and load messages, then its terrains, objects and robots with
// their links, filtered by a text box (case-insensitive, on names). A click selects the body,
// as a click in the view does, and the selected body is highlighted in both.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/widgets/item_registry.h"

namespace lamina::ui {

std::string BodyDescription(const core::WorldDesc& world, int id) {
  const core::WorldId body = world.Resolve(id);
  const std::string number = " (id " + std::to_string(id) + ")";
  switch (body.kind) {
    case core::WorldId::Kind::kTerrain:
      return "terrain '" + world.terrains[body.index].name + "'" + number;
    case core::WorldId::Kind::kRigidObject:
      return "object '" + world.objects[body.index].name + "'" + number;
    case core::WorldId::Kind::kRobot:
      return "robot '" + world.robots[body.index].name + "'" + number;
    case core::WorldId::Kind::kRobotLink:
      return "link '" + world.robots[body.index].links[body.link].name + "' of robot '" +
             world.robots[body.index].name + "'" + number;
    case core::WorldId::Kind::kInvalid:
      break;
  }
  return "nothing";
}

namespace {

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool Matches(const std::string& name, const std::string& filter) {
  return filter.empty() || Lower(name).find(filter) != std::string::npos;
}

// one selectable leaf; a click selects `id`
void Leaf(const std::string& name, int id, ViewerState* state) {
  const bool selected = state->selected_id == id;
  const std::string label = name + "##" + std::to_string(id);
  if (ImGui::Selectable(label.c_str(), selected)) state->selected_id = id;
  RecordItem("tree." + std::to_string(id), name);
  if (selected && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY();
}

template <typename Elements, typename IdOf>
void DrawGroup(const char* title, const Elements& elements, IdOf id_of, const std::string& filter,
               ViewerState* state) {
  if (elements.empty()) return;
  const std::string header = std::string(title) + " (" + std::to_string(elements.size()) + ")";
  ImGui::SetNextItemOpen(true, ImGuiCond_Once);
  if (!ImGui::TreeNode(header.c_str())) return;
  for (size_t i = 0; i < elements.size(); ++i) {
    if (Matches(elements[i].name, filter))
      Leaf(elements[i].name, id_of(static_cast<int>(i)), state);
  }
  ImGui::TreePop();
}

bool RobotMatches(const core::RobotDesc& robot, const std::string& filter) {
  return Matches(robot.name, filter) ||
         std::any_of(robot.links.begin(), robot.links.end(),
                     [&](const auto& link) { return Matches(link.name, filter); });
}

void DrawRobot(const core::WorldDesc& world, int r, const std::string& filter, ViewerState* state) {
  const core::RobotDesc& robot = world.robots[r];
  const int robot_id = world.RobotId(r);
  const bool selected = state->selected_id == robot_id;
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
  if (selected) flags |= ImGuiTreeNodeFlags_Selected;
  if (!filter.empty()) ImGui::SetNextItemOpen(true);
  const bool open = ImGui::TreeNodeEx(robot.name.c_str(), flags, "robot %s (%d links)",
                                      robot.name.c_str(), robot.dof());
  if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) state->selected_id = robot_id;
  if (!open) return;
  for (int l = 0; l < robot.dof(); ++l) {
    if (Matches(robot.links[l].name, filter)) {
      Leaf(robot.links[l].name, world.RobotLinkId(r, l), state);
    }
  }
  ImGui::TreePop();
}

void DrawTree(const core::WorldDesc& world, ViewerState* state) {
  std::array<char, 128> buffer{};
  std::strncpy(buffer.data(), state->tree_filter.c_str(), buffer.size() - 1);
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##filter", "filter by name", buffer.data(), buffer.size());
  state->tree_filter = buffer.data();
  const std::string filter = Lower(state->tree_filter);
  ImGui::BeginChild("tree", ImVec2(0, 0), false);
  DrawGroup(
      "terrains", world.terrains, [&](int i) { return world.TerrainId(i); }, filter, state);
  DrawGroup(
      "objects", world.objects, [&](int i) { return world.ObjectId(i); }, filter, state);
  if (!world.robots.empty()) {
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (ImGui::TreeNode("robots")) {
      for (int r = 0; r < static_cast<int>(world.robots.size()); ++r) {
        if (RobotMatches(world.robots[r], filter)) DrawRobot(world, r, filter, state);
      }
      ImGui::TreePop();
    }
  }
  ImGui::EndChild();
}

void DrawLoadMessages(const ViewerState& state) {
  if (state.load_messages.empty()) return;
  const long lines = std::count(state.load_messages.begin(), state.load_messages.end(), '\n');
  const std::string title = (state.load_failed ? "cannot open: " : "") + std::to_string(lines) +
                            " load message" + (lines == 1 ? "" : "s") + "###messages";
  if (state.load_failed) ImGui::SetNextItemOpen(true);
  if (!ImGui::CollapsingHeader(title.c_str())) return;
  if (state.load_failed) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
  ImGui::BeginChild("messages", ImVec2(0, state.load_failed ? 0.0f : 150.0f), true,
                    ImGuiWindowFlags_HorizontalScrollbar);
  ImGui::TextUnformatted(state.load_messages.c_str());
  ImGui::EndChild();
  if (state.load_failed) ImGui::PopStyleColor();
}

}  // namespace

void DrawWorldTree(const PanelContext& context) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float top = MenuBarHeight() + 320.0f;  // below the Simulation panel
  ImGui::SetNextWindowPos(ImVec2(10, top), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(300, std::max(150.0f, display.y - top - 36.0f)),
                           ImGuiCond_FirstUseEver);
  if (ImGui::Begin("World", &context.state->panels.world_tree)) {
    const SessionFrame& frame = context.frame;
    if (frame.loaded) {
      ImGui::Text("%s%s", frame.world->name.c_str(), frame.dirty ? " (unsaved changes)" : "");
      ImGui::TextDisabled("%s", frame.path.empty() ? "(not saved yet)" : frame.path.c_str());
    }
    DrawLoadMessages(*context.state);
    if (frame.loaded) DrawTree(*frame.world, context.state);
  }
  ImGui::End();
}

}  // namespace lamina::ui
