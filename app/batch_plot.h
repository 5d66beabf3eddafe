// SPDX-License-Identifier: MIT
// The histogram of `lamina-headless batch --plot ITEM`: bars, axes, tick labels and a title
// drawn into an RGBA buffer on the CPU (text with stb_easy_font) and written as PNG. No GL.
#pragma once

#include <string>
#include <vector>

namespace lamina::app {

/// Writes a histogram of `values` (finite; the bins span [min, max], sqrt(n) of them, between
/// 5 and 40) titled `title` as a PNG; false with `error` when there is nothing to plot or the
/// file cannot be written.
bool WriteHistogramPng(const std::string& path, const std::vector<double>& values,
                       const std::string& title, std::string* error);

}  // namespace lamina::app
