// SPDX-License-Identifier: MIT
// Named ImGui items, for scripted UI tests: while recording is on (the editor's --trace), a panel
// names the item it has just drawn — `RecordItem("objects[0].kFriction", "0.5")` — and the trace
// writes every name with its rectangle and the text it shows. A test then clicks where a user
// would click and reads what a user would read, instead of guessing pixel positions that move
// whenever a panel changes. Off (the default) it costs one branch per call.
//
// Rectangles are in ImGui's display coordinates: pixels from the window's top-left corner, y
// down (the same pixels xdotool moves to in a window at the screen's origin). An item clipped
// away (a scrolled-off row, a collapsed panel) is not recorded. Names are unique per frame; a
// second item of the same name replaces the first.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace lamina::ui {

struct RecordedItem {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< top-left and bottom-right corners (pixels)
  std::string text;                      ///< what the item shows ("" when not given)
};

void SetItemRecording(bool on);
bool ItemRecording();
/// Forgets the items of the previous frame (call before the panels are drawn).
void ClearRecordedItems();
/// Records the last ImGui item (ImGui::GetItemRectMin/Max) under `name`, when recording and
/// when the item is visible.
void RecordItem(std::string_view name, std::string_view text = {});
const std::map<std::string, RecordedItem, std::less<>>& RecordedItems();

}  // namespace lamina::ui
