// SPDX-License-Identifier: MIT
// The inspector's "contacts now": one entry per partner the selected body touches — the pair's
// blended friction, restitution, stiffness and damping (and rolling and spinning friction when
// either body has them) exactly as the contact rows use them with the rule that produced each
// (hover a value for it), the contact count, the deepest overlap against the padding sum, the
// normal force and the soft contact's ERP/CFM (core::ReadContacts).
#include <cstdio>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace lamina::ui {

namespace {

// one blended value with its rule as the tooltip
void BlendRow(const char* name, const core::BlendReadout& blend, const char* unit) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  ImGui::TableNextColumn();
  ImGui::Text("%.4g%s", blend.value, unit);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", blend.rule.c_str());
  ImGui::TableNextColumn();
  ImGui::TextDisabled("%s", blend.rule.c_str());
}

void DrawPair(const core::PairReadout& pair) {
  const std::string header = pair.partner_name + " (id " + std::to_string(pair.partner) + ")";
  ImGui::SetNextItemOpen(true, ImGuiCond_Once);
  if (!ImGui::TreeNode(header.c_str())) return;
  if (ImGui::BeginTable("blend", 3, ImGuiTableFlags_SizingFixedFit)) {
    BlendRow("friction", pair.friction, "");
    BlendRow("restitution", pair.restitution, "");
    BlendRow("stiffness", pair.stiffness, " N/m");
    BlendRow("damping", pair.damping, " N·s/m");
    // Lamina's rolling resistance, shown where either body has it
    if (pair.rolling.own != 0.0 || pair.rolling.partner != 0.0) {
      BlendRow("rolling", pair.rolling, " m");
    }
    if (pair.spinning.own != 0.0 || pair.spinning.partner != 0.0) {
      BlendRow("spinning", pair.spinning, " m");
    }
    ImGui::EndTable();
  }
  ImGui::Text("%d contact%s, overlap %.3g mm of %.3g mm padding", pair.contact_count,
              pair.contact_count == 1 ? "" : "s", pair.max_depth * 1e3, pair.padding_sum * 1e3);
  if (pair.normal_force_known) {
    ImGui::Text("normal force %.4g N, %s", pair.normal_force, pair.law.c_str());
  } else {
    ImGui::TextDisabled("%s; %s", pair.normal_force_note.c_str(), pair.law.c_str());
  }
  ImGui::TreePop();
}

}  // namespace

void DrawContactsNow(const PanelContext& context, int id) {
  const std::vector<core::PairReadout>& pairs = context.frame.sampled_contacts;
  const std::string header = "contacts now (" + std::to_string(pairs.size()) + ")###contacts";
  if (!ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (context.state->selected_id != id) return;  // the frame follows the selection next frame
  if (pairs.empty()) ImGui::TextDisabled("touches nothing");
  for (const core::PairReadout& pair : pairs) {
    ImGui::PushID(pair.partner);
    DrawPair(pair);
    ImGui::PopID();
  }
}

}  // namespace lamina::ui
