// SPDX-License-Identifier: MIT
#include "ui/widgets/item_registry.h"

#include <imgui.h>

namespace lamina::ui {

namespace {

struct Registry {
  bool on = false;
  std::map<std::string, RecordedItem, std::less<>> items;
};

Registry& TheRegistry() {
  static Registry registry;
  return registry;
}

}  // namespace

void SetItemRecording(bool on) {
  TheRegistry().on = on;
}

bool ItemRecording() {
  return TheRegistry().on;
}

void ClearRecordedItems() {
  TheRegistry().items.clear();
}

void RecordItem(std::string_view name, std::string_view text) {
  Registry& registry = TheRegistry();
  if (!registry.on || !ImGui::IsItemVisible()) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  registry.items.insert_or_assign(std::string(name),
                                  RecordedItem{min.x, min.y, max.x, max.y, std::string(text)});
}

const std::map<std::string, RecordedItem, std::less<>>& RecordedItems() {
  return TheRegistry().items;
}

}  // namespace lamina::ui
