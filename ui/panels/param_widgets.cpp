// SPDX-License-Identifier: MIT
#include "ui/panels/param_widgets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>  // TempInputIsActive: is the user typing into a drag field?

#include "core/edit/document.h"
#include "ui/widgets/item_registry.h"

namespace lamina::ui {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDegrees = 180.0 / 3.14159265358979323846;

// what a widget did this frame
struct WidgetResult {
  bool changed = false;
  core::ParamValue value;
};

// ---- undo groups: a widget's activation to its deactivation is one entry ---------------

// (the group's label is its first edit's: "kFriction of block")
void TrackGroup(EditorActions* actions) {
  if (ImGui::IsItemActivated()) actions->BeginWidgetGroup();
  if (ImGui::IsItemDeactivated()) actions->EndWidgetGroup();
}

// drag speed: 1 % of the value's size per pixel, or a small absolute step at 0
float DragSpeed(double value) {
  const double size = std::isfinite(value) ? std::abs(value) : 1.0;
  return static_cast<float>(std::max(size * 0.01, 1e-4));
}

// ---- typed values: applied when the field is left, not per keystroke ----------------------

// Typing into a drag field (Ctrl+click or double-click) gives ImGui a value per keystroke: "0",
// "0.", "0.05". They are held back and only the number in the field when it is left (Enter,
// Tab, a click elsewhere) is applied, so a friction of 0 or a stiffness the table refuses on
// the way to the typed number never reaches the simulation. Escape, or text that is not a
// number, leaves the value as it was. The held number belongs to one field of one element: if
// the selection changes while typing, it is dropped rather than given to another body.
struct TypedValue {
  std::string field;  ///< element path and key ("objects[0].kFriction")
  double value = 0.0;
  int frame = -1;  ///< ImGui frame when it was last seen being typed
  bool held = false;
};

TypedValue& Typed() {
  static TypedValue typed;  // one field has the keyboard at a time
  return typed;
}

// the text of the field being typed into, as a number (nullopt: not a number, e.g. "" or "-")
std::optional<double> TypedNumber(ImGuiID id) {
  const ImGuiInputTextState* state = ImGui::GetInputTextState(id);
  if (state == nullptr) return std::nullopt;
  std::string text;
  for (int i = 0; i < state->CurLenW; ++i) {
    if (state->TextW[i] >= 128) return std::nullopt;
    text += static_cast<char>(state->TextW[i]);
  }
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  while (end != nullptr && *end == ' ') ++end;
  if (end == text.c_str() || end == nullptr || *end != '\0') return std::nullopt;
  return number;
}

// call right after the drag widget of `field`; adjusts what it reports
void HoldWhileTyping(const std::string& field, bool* changed, double* value) {
  TypedValue& typed = Typed();
  const ImGuiID id = ImGui::GetItemID();
  const int frame = ImGui::GetFrameCount();
  if (ImGui::TempInputIsActive(id)) {
    const std::optional<double> number = TypedNumber(id);
    typed = {field, number.value_or(0.0), frame, number.has_value()};
    *changed = false;
    return;
  }
  const bool mine = typed.held && typed.field == field && typed.frame >= frame - 1;
  if (mine && ImGui::IsItemDeactivated()) {
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      *changed = false;      // (ImGui's revert to the text the field started with)
    } else if (!*changed) {  // (a keystroke in the same frame as Enter: ImGui's value is final)
      *changed = typed.value != *value;
      *value = typed.value;
    }
  }
  if (typed.held && (mine || typed.frame < frame - 1)) typed = {};  // used, or left undrawn
}

// ---- widgets by type --------------------------------------------------------------------

// `finite`: what unticking `inf` gives
WidgetResult RealWidget(const std::string& field, const core::ParamSpec& spec, double value,
                        double finite, EditorActions* actions) {
  WidgetResult result;
  const bool infinite = std::isinf(value);
  if (spec.allow_inf) {
    ImGui::SetNextItemWidth(-50.0f);
  } else {
    ImGui::SetNextItemWidth(-1.0f);
  }
  double shown = infinite ? 0.0 : value;
  if (infinite) ImGui::BeginDisabled();
  result.changed = ImGui::DragScalar("##v", ImGuiDataType_Double, &shown, DragSpeed(value), nullptr,
                                     nullptr, infinite ? "inf" : "%.6g");
  HoldWhileTyping(field, &result.changed, &shown);
  TrackGroup(actions);
  if (infinite) ImGui::EndDisabled();
  if (spec.allow_inf) {
    ImGui::SameLine();
    bool inf = infinite;
    if (ImGui::Checkbox("inf", &inf)) {
      result.changed = true;
      shown = inf ? kInf : finite;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("infinite: rigid / no limit");
  }
  result.value = {shown};
  return result;
}

WidgetResult IntegerWidget(const std::string& field, double value, EditorActions* actions) {
  WidgetResult result;
  long long shown = static_cast<long long>(value);
  ImGui::SetNextItemWidth(-1.0f);
  result.changed = ImGui::DragScalar("##v", ImGuiDataType_S64, &shown, 0.2f);
  double typed = static_cast<double>(shown);
  HoldWhileTyping(field, &result.changed, &typed);
  TrackGroup(actions);
  result.value = {typed};
  return result;
}

WidgetResult BoolWidget(double value) {
  WidgetResult result;
  bool shown = value != 0.0;
  result.changed = ImGui::Checkbox("##v", &shown);
  result.value = {shown ? 1.0 : 0.0};
  return result;
}

WidgetResult ChoiceWidget(const core::ParamSpec& spec, double value) {
  WidgetResult result;
  const int current = static_cast<int>(value);
  const std::string preview = current >= 0 && current < static_cast<int>(spec.choices.size())
                                  ? std::string(spec.choices[current])
                                  : std::to_string(current);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::BeginCombo("##v", preview.c_str())) {
    for (int i = 0; i < static_cast<int>(spec.choices.size()); ++i) {
      const std::string name(spec.choices[i]);
      if (ImGui::Selectable(name.c_str(), i == current) && i != current) {
        result = {true, {static_cast<double>(i)}};
      }
    }
    ImGui::EndCombo();
  }
  return result;
}

WidgetResult Vec3Widget(const core::ParamValue& value, EditorActions* actions) {
  WidgetResult result{false, value};
  ImGui::SetNextItemWidth(-1.0f);
  const double largest = std::max({std::abs(value[0]), std::abs(value[1]), std::abs(value[2])});
  result.changed = ImGui::DragScalarN("##v", ImGuiDataType_Double, result.value.data(), 3,
                                      DragSpeed(largest), nullptr, nullptr, "%.4g");
  TrackGroup(actions);
  return result;
}

// Klamp't's roll-pitch-yaw: R = Rz(yaw) Ry(pitch) Rx(roll), in radians
core::Vec3 RollPitchYaw(const core::Mat3& r) {
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  if (std::abs(r(2, 0)) > 1.0 - 1e-12) {  // gimbal lock: all the turn in yaw
    return {0.0, pitch, std::atan2(-r(0, 1), r(1, 1))};
  }
  return {std::atan2(r(2, 1), r(2, 2)), pitch, std::atan2(r(1, 0), r(0, 0))};
}

core::Mat3 RotationOf(const core::Vec3& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), core::Vec3::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), core::Vec3::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), core::Vec3::UnitX()))
      .toRotationMatrix();
}

WidgetResult PoseWidget(const core::ParamValue& value, EditorActions* actions) {
  core::Pose pose = core::ValueToPose(value);
  core::Vec3 position = pose.translation();
  core::Vec3 angles = RollPitchYaw(pose.linear()) * kDegrees;
  ImGui::SetNextItemWidth(-1.0f);
  bool changed = ImGui::DragScalarN("##p", ImGuiDataType_Double, position.data(), 3, 0.005f,
                                    nullptr, nullptr, "%.4g m");
  TrackGroup(actions);
  ImGui::SetNextItemWidth(-1.0f);
  changed |= ImGui::DragScalarN("##r", ImGuiDataType_Double, angles.data(), 3, 0.5f, nullptr,
                                nullptr, "%.2f°");
  TrackGroup(actions);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("roll, pitch, yaw (degrees)");
  if (!changed) return {false, value};
  pose.translation() = position;
  pose.linear() = RotationOf(angles / kDegrees);
  return {true, core::PoseToValue(pose)};
}

WidgetResult TwistWidget(const core::ParamValue& value, EditorActions* actions) {
  WidgetResult result{false, value};
  ImGui::SetNextItemWidth(-1.0f);
  result.changed = ImGui::DragScalarN("##w", ImGuiDataType_Double, result.value.data(), 3, 0.01f,
                                      nullptr, nullptr, "%.3g rad/s");
  TrackGroup(actions);
  ImGui::SetNextItemWidth(-1.0f);
  result.changed |= ImGui::DragScalarN("##l", ImGuiDataType_Double, result.value.data() + 3, 3,
                                       0.01f, nullptr, nullptr, "%.3g m/s");
  TrackGroup(actions);
  return result;
}

// ranges, inertias, per-link vectors: the table's text form, applied on Enter
WidgetResult TextWidget(const core::ParamSpec& spec, const core::ParamValue& value) {
  std::array<char, 512> buffer{};
  const std::string text = core::FormatParamValue(spec, value);
  std::strncpy(buffer.data(), text.c_str(), buffer.size() - 1);
  ImGui::SetNextItemWidth(-1.0f);
  if (!ImGui::InputText("##v", buffer.data(), buffer.size(),
                        ImGuiInputTextFlags_EnterReturnsTrue)) {
    return {false, value};
  }
  std::string error;
  std::optional<core::ParamValue> parsed = core::ParseParamValue(spec, buffer.data(), &error);
  if (!parsed) return {false, value};  // unreadable text: the field shows the value again
  return {*parsed != value, *parsed};
}

WidgetResult DrawWidget(const std::string& field, const core::ParamSpec& spec,
                        const core::ParamValue& value, double finite, EditorActions* actions) {
  using T = core::ParamType;
  switch (spec.type) {
    case T::kReal:
      return RealWidget(field, spec, value.at(0), finite, actions);
    case T::kInteger:
      return IntegerWidget(field, value.at(0), actions);
    case T::kBool:
      return BoolWidget(value.at(0));
    case T::kChoice:
      return ChoiceWidget(spec, value.at(0));
    case T::kVec3:
      return Vec3Widget(value, actions);
    case T::kPose:
      return PoseWidget(value, actions);
    case T::kTwist:
      return TwistWidget(value, actions);
    case T::kRange:
    case T::kInertia:
    case T::kVector:
      break;
  }
  return TextWidget(spec, value);
}

// ---- the label column: name, unit, tooltip, back-to-file button -------------------------

std::string LabelText(const core::ParamSpec& spec) {
  std::string label(spec.label);
  if (!spec.unit.empty()) label += " (" + std::string(spec.unit) + ")";
  return label;
}

void LabelTooltip(const core::ParamSpec& spec) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::SetTooltip("%s\n%s: %s\n%s; %s", std::string(spec.help).c_str(),
                    std::string(spec.key).c_str(), core::ParamRule(spec).c_str(),
                    ApplyKindText(spec.apply), spec.klampt ? "Klamp't attribute" : "Lamina's");
}

std::optional<core::ParamValue> FileValue(const ParamRowContext& row, const core::ParamSpec& spec) {
  if (!row.file_world) return std::nullopt;
  const std::optional<core::ElementIndex> element = core::ResolveRef(*row.file_world, row.ref);
  if (!element) return std::nullopt;
  return core::GetParam(*row.file_world, *element, spec);
}

// what unticking `inf` gives: the file's value when it is finite, else 1 (or the row's minimum)
double FiniteFallback(const ParamRowContext& row, const core::ParamSpec& spec) {
  const std::optional<core::ParamValue> file = FileValue(row, spec);
  if (file && file->size() == 1 && std::isfinite((*file)[0])) return (*file)[0];
  return std::isfinite(spec.min) ? std::max(spec.min, 1.0) : 1.0;
}

void RevertButton(const ParamRowContext& row, const core::ParamSpec& spec,
                  const core::ParamValue& shown, EditorActions* actions) {
  const std::optional<core::ParamValue> file = FileValue(row, spec);
  // (a file value of another size belongs to a robot of another shape: nothing to go back to)
  const bool differs = file && file->size() == shown.size() && *file != shown;
  ImGui::SameLine(ImGui::GetContentRegionAvail().x - 14.0f + ImGui::GetCursorPosX());
  if (!differs) ImGui::BeginDisabled();
  if (ImGui::SmallButton("<")) actions->SetParam(row.ref, spec, *file);
  if (ItemRecording())
    RecordItem(core::ElementPath(row.element) + "." + std::string(spec.key) + "<");
  if (!differs) ImGui::EndDisabled();
  if (differs && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("back to the file's value: %s", core::FormatParamValue(spec, *file).c_str());
  }
}

}  // namespace

const char* ApplyKindText(core::ParamApply apply) {
  switch (apply) {
    case core::ParamApply::kLive:
      return "applies live, from the next step";
    case core::ParamApply::kRebuildGeometry:
      return "rebuilds the body's geometry, keeping the state";
    case core::ParamApply::kRebuildSimulator:
      return "rebuilds the simulation, keeping its state";
    case core::ParamApply::kOnReset:
      return "an initial condition: takes effect at Reset";
  }
  return "";
}

void DrawParamRow(const ParamRowContext& row, const core::ParamSpec& spec, EditorActions* actions) {
  const std::optional<core::ParamValue> current = core::GetParam(row.world, row.element, spec);
  if (!current) return;
  const core::ParamValue& shown = actions->Shown(row.ref, spec, *current);
  ImGui::PushID(core::ParamId(spec));
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(LabelText(spec).c_str());
  LabelTooltip(spec);
  RevertButton(row, spec, shown, actions);
  ImGui::TableNextColumn();
  ImGui::BeginGroup();
  const std::string field = core::ElementPath(row.element) + "." + std::string(spec.key);
  const WidgetResult result = DrawWidget(field, spec, shown, FiniteFallback(row, spec), actions);
  ImGui::EndGroup();
  if (ItemRecording()) RecordItem(field, core::FormatParamValue(spec, shown));
  if (result.changed) actions->SetParam(row.ref, spec, result.value);
  ImGui::PopID();
}

void DrawParamTable(const char* id, const ParamRowContext& row, core::ElementKind kind,
                    EditorActions* actions, bool (*filter)(const core::ParamSpec&)) {
  if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_SizingStretchProp)) return;
  ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch, 0.45f);
  ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 0.55f);
  for (const core::ParamSpec* spec : core::ParamsOf(kind)) {
    if (!filter || filter(*spec)) DrawParamRow(row, *spec, actions);
  }
  ImGui::EndTable();
}

}  // namespace lamina::ui
