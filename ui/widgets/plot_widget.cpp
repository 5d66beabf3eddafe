// SPDX-License-Identifier: MIT
#include "ui/widgets/plot_widget.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <imgui_internal.h>  // ImGui::SetItemUsingMouseWheel (1.86)

namespace lamina::ui {
namespace {

constexpr float kPad = 4.0f;            // px between the frame, labels and text
constexpr float kXTickSpacing = 90.0f;  // px between time ticks, about
constexpr float kYTickSpacing = 32.0f;  // px between value ticks, about
constexpr double kWheelZoom = 0.8;      // span factor per wheel notch

// Distinct line colours on a dark background (Tableau 10, brightened).
constexpr std::array<ImU32, 8> kColours = {
    IM_COL32(90, 160, 230, 255),  IM_COL32(255, 150, 50, 255),  IM_COL32(90, 200, 90, 255),
    IM_COL32(240, 80, 80, 255),   IM_COL32(180, 140, 220, 255), IM_COL32(200, 150, 120, 255),
    IM_COL32(240, 140, 210, 255), IM_COL32(200, 200, 90, 255)};

ImU32 SeriesColour(std::size_t index) {
  return kColours[index % kColours.size()];
}

bool Visible(const PlotView& view, const PlotSeries& series) {
  return view.hidden.count(series.name()) == 0;
}

// ---- the header: title, legend, Freeze and CSV ----

// Keeps the next item on this line when `width` still fits, otherwise starts a new line.
void SameLineIfFits(float width) {
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  ImGui::SameLine();
  if (ImGui::GetCursorScreenPos().x + width > right) ImGui::NewLine();
}

void ToggleHidden(const std::string& name, PlotView* view) {
  if (!view->hidden.erase(name)) view->hidden.insert(name);
}

void LegendEntry(const PlotSeries& series, ImU32 colour, PlotView* view) {
  const std::string label = series.Label();
  const float box = ImGui::GetTextLineHeight();
  const ImVec2 size(box + kPad + ImGui::CalcTextSize(label.c_str()).x, box);
  SameLineIfFits(size.x);
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const bool visible = Visible(*view, series);
  if (ImGui::InvisibleButton(label.c_str(), size)) ToggleHidden(series.name(), view);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("click to %s", visible ? "hide" : "show");
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 box_min(at.x + 2, at.y + 2), box_max(at.x + box - 2, at.y + box - 2);
  if (visible) {
    draw->AddRectFilled(box_min, box_max, colour);
  } else {
    draw->AddRect(box_min, box_max, colour);
  }
  const ImU32 text = ImGui::GetColorU32(visible ? ImGuiCol_Text : ImGuiCol_TextDisabled);
  draw->AddText(ImVec2(at.x + box + kPad, at.y), text, label.c_str());
}

void FreezeToggle(const PlotGroup& group, PlotView* view) {
  SameLineIfFits(ImGui::CalcTextSize("Freeze").x + 2 * ImGui::GetStyle().FramePadding.x);
  if (ImGui::SmallButton(view->frozen ? "Resume" : "Freeze")) {
    view->frozen = !view->frozen;
    view->frozen_end = group.last_time();
  }
}

bool CsvButton(const PlotGroup& group, PlotView* view) {
  if (view->csv_path.empty()) return false;
  SameLineIfFits(ImGui::CalcTextSize("CSV").x + 2 * ImGui::GetStyle().FramePadding.x);
  const bool pressed = ImGui::SmallButton("CSV");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("write %s", view->csv_path.c_str());
  if (!pressed) return false;
  std::string error;
  const bool wrote = WriteCsv(group, view->csv_path, &error);
  view->message = wrote ? "wrote " + view->csv_path : error;
  return true;
}

bool DrawHeader(const PlotGroup& group, PlotView* view) {
  ImGui::TextUnformatted(group.title().c_str());
  for (std::size_t i = 0; i < group.series().size(); ++i) {
    ImGui::PushID(int(i));  // two series may share a label
    LegendEntry(group.series()[i], SeriesColour(i), view);
    ImGui::PopID();
  }
  FreezeToggle(group, view);
  const bool pressed = CsvButton(group, view);
  if (!view->message.empty()) {
    SameLineIfFits(ImGui::CalcTextSize(view->message.c_str()).x);
    ImGui::TextDisabled("%s", view->message.c_str());
  }
  return pressed;
}

// ---- the plot area ----

// The visible series, decimated to the pixel columns, and where they are drawn.
struct PlotArea {
  ImVec2 min, max;  // the framed rectangle, screen px
  TimeWindow window;
  ValueRange range;
  Ticks x_ticks, y_ticks;
  std::string y_unit;  // "[J]" when every visible series has that unit, else ""
  std::vector<std::vector<PlotSample>> lines;  // per series; empty when hidden

  float X(double t) const {
    return min.x + float((t - window.t0) / (window.t1 - window.t0)) * (max.x - min.x);
  }
  float Y(double y) const {
    return max.y - float((y - range.lo) / (range.hi - range.lo)) * (max.y - min.y);
  }
  double TimeAt(float x) const {
    return window.t0 + (window.t1 - window.t0) * double((x - min.x) / (max.x - min.x));
  }
};

void DecimateSeries(const PlotGroup& group, const PlotView& view, PlotArea* area) {
  const int columns = std::max(1, int(area->max.x - area->min.x));
  ValueRange range = EmptyRange();
  area->lines.assign(group.series().size(), {});
  for (std::size_t i = 0; i < group.series().size(); ++i) {
    if (!Visible(view, group.series()[i])) continue;
    area->lines[i] = DecimatedWindow(group.series()[i], area->window, columns);
    ExtendRange(area->lines[i], &range);
  }
  area->range = PaddedRange(range);
}

// Ticks about `spacing` px apart along `pixels`; closer, down to `min_spacing` px, while that
// gives fewer than two.
Ticks AxisTicks(double lo, double hi, float pixels, float spacing, float min_spacing) {
  const double min_step = (hi - lo) * double(min_spacing / pixels);
  int n = std::max(2, int(pixels / spacing));
  Ticks ticks = NiceTicks(lo, hi, n);
  while (ticks.values.size() < 2 && n < 64) {
    Ticks denser = NiceTicks(lo, hi, ++n);
    if (denser.step < min_step) break;
    ticks = std::move(denser);
  }
  return ticks;
}

float WidestLabel(const Ticks& ticks) {
  float widest = 0.0f;
  for (double v : ticks.values) {
    widest = std::max(widest, ImGui::CalcTextSize(TickLabel(ticks, v).c_str()).x);
  }
  return widest;
}

// "[unit]" when every visible series has that unit, else "".
std::string CommonUnit(const PlotGroup& group, const PlotView& view) {
  std::string unit;
  bool first = true;
  for (const PlotSeries& s : group.series()) {
    if (!Visible(view, s)) continue;
    if (!first && s.unit() != unit) return "";
    unit = s.unit();
    first = false;
  }
  return unit.empty() ? "" : "[" + unit + "]";
}

// Lays out the area in [origin, origin + size): the y labels to the left, time labels below.
PlotArea LayOut(const PlotGroup& group, const PlotView& view, ImVec2 origin, ImVec2 size) {
  PlotArea area;
  const double t_end = view.frozen ? view.frozen_end : group.last_time();
  area.window = ScrollingWindow(group, view.span, t_end);
  area.min = origin;
  area.max = ImVec2(origin.x + size.x, origin.y + size.y - ImGui::GetTextLineHeight() - kPad);
  DecimateSeries(group, view, &area);
  const float height = area.max.y - area.min.y;
  const float line = ImGui::GetTextLineHeight();
  area.y_ticks = AxisTicks(area.range.lo, area.range.hi, height, kYTickSpacing, 1.3f * line);
  area.y_unit = CommonUnit(group, view);
  const float unit_width = ImGui::CalcTextSize(area.y_unit.c_str()).x;
  area.min.x += std::max(WidestLabel(area.y_ticks), unit_width) + 2 * kPad;
  const float width = area.max.x - area.min.x;
  area.x_ticks = AxisTicks(area.window.t0, area.window.t1, width, kXTickSpacing, 4.0f * line);
  return area;
}

void DrawYAxis(const PlotArea& area, ImDrawList* draw) {
  const ImU32 grid = ImGui::GetColorU32(ImGuiCol_Border, 0.5f);
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  const float half_line = 0.5f * ImGui::GetTextLineHeight();
  for (double v : area.y_ticks.values) {
    const float y = std::round(area.Y(v));
    draw->AddLine(ImVec2(area.min.x, y), ImVec2(area.max.x, y), grid);
    const std::string label = TickLabel(area.y_ticks, v);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    const float top = std::clamp(y - half_line, area.min.y, area.max.y - 2 * half_line);
    draw->AddText(ImVec2(area.min.x - kPad - w, top), text, label.c_str());
  }
}

void DrawXAxis(const PlotArea& area, ImDrawList* draw) {
  const ImU32 grid = ImGui::GetColorU32(ImGuiCol_Border, 0.5f);
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  const float right = area.max.x - ImGui::CalcTextSize("t [s]").x;
  for (double t : area.x_ticks.values) {
    const float x = std::round(area.X(t));
    draw->AddLine(ImVec2(x, area.min.y), ImVec2(x, area.max.y), grid);
    const std::string label = TickLabel(area.x_ticks, t);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    const float left = std::clamp(x - 0.5f * w, area.min.x, area.max.x - w);
    if (left + w < right - kPad)
      draw->AddText(ImVec2(left, area.max.y + kPad), text, label.c_str());
  }
  draw->AddText(ImVec2(right, area.max.y + kPad), ImGui::GetColorU32(ImGuiCol_TextDisabled),
                "t [s]");
}

// The y unit in the corner left of the time labels, below the value labels.
void DrawUnit(const PlotArea& area, ImDrawList* draw) {
  const float w = ImGui::CalcTextSize(area.y_unit.c_str()).x;
  draw->AddText(ImVec2(area.min.x - kPad - w, area.max.y + kPad),
                ImGui::GetColorU32(ImGuiCol_TextDisabled), area.y_unit.c_str());
}

void DrawLine(const PlotArea& area, const std::vector<PlotSample>& line, ImU32 colour,
              ImDrawList* draw) {
  std::vector<ImVec2> points;
  points.reserve(line.size());
  for (const PlotSample& s : line) points.emplace_back(area.X(s.t), area.Y(s.y));
  if (points.size() == 1) draw->AddCircleFilled(points[0], 2.0f, colour);
  if (points.size() >= 2) draw->AddPolyline(points.data(), int(points.size()), colour, 0, 1.5f);
}

void DrawLines(const PlotArea& area, ImDrawList* draw) {
  draw->PushClipRect(area.min, area.max, true);
  for (std::size_t i = 0; i < area.lines.size(); ++i) {
    DrawLine(area, area.lines[i], SeriesColour(i), draw);
  }
  draw->PopClipRect();
}

// ---- hover and zoom ----

void HoverTooltip(const PlotGroup& group, const PlotView& view, double t) {
  ImGui::BeginTooltip();
  ImGui::Text("t = %.4f s", t);
  for (std::size_t i = 0; i < group.series().size(); ++i) {
    const PlotSeries& s = group.series()[i];
    if (!Visible(view, s)) continue;
    const ImVec4 colour = ImGui::ColorConvertU32ToFloat4(SeriesColour(i));
    ImGui::TextColored(colour, "%s: %.6g %s", s.name().c_str(), ValueNear(s, t), s.unit().c_str());
  }
  ImGui::EndTooltip();
}

void Hover(const PlotGroup& group, const PlotView& view, const PlotArea& area, ImDrawList* draw) {
  const float x = ImGui::GetIO().MousePos.x;
  if (x < area.min.x || x > area.max.x) return;
  draw->AddLine(ImVec2(x, area.min.y), ImVec2(x, area.max.y),
                ImGui::GetColorU32(ImGuiCol_Text, 0.6f));
  HoverTooltip(group, view, area.TimeAt(x));
}

void Zoom(PlotView* view) {
  const float wheel = ImGui::GetIO().MouseWheel;
  if (wheel == 0.0f) return;
  view->span = std::clamp(view->span * std::pow(kWheelZoom, double(wheel)), PlotView::kMinSpan,
                          PlotView::kMaxSpan);
}

// Opaque, so that the 3D view behind a translucent window does not show through the lines.
void DrawBackground(const PlotArea& area, ImDrawList* draw) {
  ImVec4 window = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
  window.w = 1.0f;
  draw->AddRectFilled(area.min, area.max, ImGui::ColorConvertFloat4ToU32(window));
  draw->AddRectFilled(area.min, area.max, ImGui::GetColorU32(ImGuiCol_FrameBg));
}

void DrawArea(const PlotGroup& group, PlotView* view, ImVec2 size) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##area", size);
  ImGui::SetItemUsingMouseWheel();
  const PlotArea area = LayOut(group, *view, origin, size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  DrawBackground(area, draw);
  DrawYAxis(area, draw);
  DrawXAxis(area, draw);
  DrawLines(area, draw);
  DrawUnit(area, draw);
  draw->AddRect(area.min, area.max, ImGui::GetColorU32(ImGuiCol_Border));
  if (!ImGui::IsItemHovered()) return;
  Hover(group, *view, area, draw);
  Zoom(view);
}

// The whole plot's size: `size` with 0 meaning the available width or 12 text lines.
ImVec2 TotalSize(ImVec2 size) {
  const float width = size.x > 0.0f ? size.x : std::max(ImGui::GetContentRegionAvail().x, 100.0f);
  const float height = size.y > 0.0f ? size.y : 12.0f * ImGui::GetTextLineHeightWithSpacing();
  return ImVec2(width, height);
}

// What the header (one line or more) left of `total` for the area, starting at `top`.
ImVec2 AreaSize(ImVec2 total, float top) {
  const float used = ImGui::GetCursorScreenPos().y - top;
  return ImVec2(total.x, std::max(total.y - used, 60.0f));
}

}  // namespace

bool DrawPlot(const char* id, const PlotGroup& group, PlotView* view, ImVec2 size) {
  ImGui::PushID(id);
  ImGui::BeginGroup();
  const ImVec2 total = TotalSize(size);
  const float top = ImGui::GetCursorScreenPos().y;
  const bool pressed = DrawHeader(group, view);
  DrawArea(group, view, AreaSize(total, top));
  ImGui::EndGroup();
  ImGui::PopID();
  return pressed;
}

}  // namespace lamina::ui
