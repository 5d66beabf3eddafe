// SPDX-License-Identifier: MIT
// Log–log line plots written as SVG text (the accuracy report's figures): decade grid lines and
// labels, one polyline with markers per series, a legend. Points that cannot go on a log axis
// (<= 0, or not finite) are left out and counted in the legend. No raster: the files are small,
// diffable text and any browser or Markdown viewer shows them.
#pragma once

#include <string>
#include <vector>

namespace lamina::core {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  ///< same length; drawn in this order
  bool dashed = false;       ///< drawn dashed (the report's runs of other engines)
};

struct LogLogPlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  int width = 640, height = 420;  ///< px
};

/// The SVG document of `plot`.
std::string LogLogSvg(const LogLogPlot& plot);

/// Least-squares slope of log(y) against log(x) over the points with x, y > 0 and finite; NaN
/// with fewer than two such points or no spread in x.
double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y);

/// Decades covering [lo, hi] (lo, hi > 0): the powers of ten from floor(log10 lo) to
/// ceil(log10 hi), at least two.
std::vector<double> DecadeTicks(double lo, double hi);

}  // namespace lamina::core
