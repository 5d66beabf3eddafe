// SPDX-License-Identifier: MIT
// Plots panel: scrolling plots of the samples the physics publishes (LiveSession::TakeSamples) —
// energy (kinetic, potential, total), the selected body's contact force and deepest overlap,
// the real-time factor and the step size, and for a selected robot link its joint's commanded
// and sensed values and its driver's torque — each with axes, a legend and a CSV export
// (ui/widgets/plot_widget.h). A reset or an undo that takes the time back clears the plots.
#pragma once

#include <vector>

#include "ui/panels/panels.h"
#include "ui/widgets/plot_data.h"
#include "ui/widgets/plot_widget.h"

namespace lamina::ui {

class PlotPanel {
 public:
  PlotPanel();
  /// Appends the new samples (call every frame, shown or not, so no sample is lost).
  void Add(const std::vector<SessionSample>& samples, const SessionFrame& frame);
  void Draw(const PanelContext& context);

 private:
  void AddJoint(const SessionSample& sample, const SessionFrame& frame);

  PlotGroup energy_, contact_, timing_, joint_;
  PlotView energy_view_, contact_view_, timing_view_, joint_view_;
  int body_ = -1;  ///< the body the contact and joint plots follow
};

}  // namespace lamina::ui
