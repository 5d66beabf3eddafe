// SPDX-License-Identifier: MIT
// A scrolling plot drawn with ImGui's draw lists (ImPlot is not packaged): a framed area with
// grid lines and tick labels (time in s on x, the series' values on y, the unit at the top when
// all visible series share one), one line per visible series in distinct colours, a legend
// (click a name to hide or show its series), a hover line with every series' value at that time
// in a tooltip, the mouse wheel zooming the visible time span between 1 s and 60 s, a "Freeze"
// toggle that stops the scrolling (samples are still recorded) and a "CSV" button that writes the
// whole group with WriteCsv. The data and its rules (capacity, NaN, time going backwards) are in
// ui/widgets/plot_data.h.
//
//   PlotGroup energy("Energy");
//   energy.AddSeries("kinetic", "J");
//   energy.AddSeries("potential", "J");
//   PlotView view;
//   view.csv_path = "energy.csv";
//   // every frame:
//   energy.AddRow(sim.time(), {sim.KineticEnergy(), sim.PotentialEnergy()});
//   if (DrawPlot("energy", energy, &view, ImVec2(0, 220))) status = view.message;
#pragma once

#include <set>
#include <string>

#include <imgui.h>

#include "ui/widgets/plot_data.h"

namespace lamina::ui {

/// The per-plot UI state, kept by the caller from frame to frame.
struct PlotView {
  static constexpr double kMinSpan = 1.0;   // s
  static constexpr double kMaxSpan = 60.0;  // s
  /// Visible time, s; the mouse wheel over the plot zooms it within [kMinSpan, kMaxSpan].
  double span = 10.0;
  /// Names of the series hidden from the plot (and its y range, the tooltip); the legend
  /// toggles them. The CSV still holds every series.
  std::set<std::string> hidden;
  /// While frozen the view stays at the time it was frozen at (frozen_end, s).
  bool frozen = false;
  double frozen_end = 0.0;
  /// Where the CSV button writes; no button when empty.
  std::string csv_path;
  /// "wrote <path>" or the error of the last CSV export; empty before one.
  std::string message;
};

/// Draws `group` at the cursor: `size` in pixels (header and plot area together; the area is
/// at least 60 px high), x <= 0 filling the available width, y <= 0 taking 12 text lines. Returns
/// true in the frame the CSV button was pressed (view->message says whether the file was written).
bool DrawPlot(const char* id, const PlotGroup& group, PlotView* view, ImVec2 size);

}  // namespace lamina::ui
