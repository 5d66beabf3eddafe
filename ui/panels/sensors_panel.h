// SPDX-License-Identifier: MIT
// Sensors panel: the sensors of the selected robot (the robot of the selected link, else the
// first robot), Klamp't SimTest's sensor plot: per sensor (the first two open at first) its
// type, link and current measurements, and a strip chart of the last seconds of every measurement
// (the legend shows and hides each; the first twelve are shown at first, as SimTest's fixed
// colours), with a CSV export. Samples of every robot are kept whether the panel is shown or not,
// so switching robots shows their history. Cameras show their size: their pictures come from
// `lamina-headless run --sensor-images` (the editor gives its simulation no camera renderer).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ui/panels/panels.h"
#include "ui/widgets/plot_data.h"
#include "ui/widgets/plot_widget.h"

namespace lamina::ui {

class SensorPanel {
 public:
  SensorPanel();
  ~SensorPanel();
  /// Appends the new samples (call every frame, shown or not).
  void Add(const std::vector<SessionSample>& samples, const SessionFrame& frame);
  void Draw(const PanelContext& context);

 private:
  struct Plot {
    std::string name, type;
    std::unique_ptr<PlotGroup> group;
    PlotView view;
  };
  void Rebuild(const SessionFrame& frame);
  bool Matches(const SessionFrame& frame) const;
  int Robot(const PanelContext& context) const;
  void DrawSensor(const core::SensorReadout& readout, Plot* plot, bool open, ViewerState* state);

  std::vector<std::vector<Plot>> plots_;  ///< per robot, per sensor
};

}  // namespace lamina::ui
