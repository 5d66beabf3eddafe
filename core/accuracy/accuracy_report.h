// SPDX-License-Identifier: MIT
// The accuracy report: the bars judged on a sweep's runs, and the runs as CSV, JSON, SVG plots
// (error against CPU time and against the step, one series per solver, with the fitted log–log
// slope) and the Markdown page docs/accuracy.md. Pure text out; the caller writes the files.
#pragma once

#include <string>
#include <vector>

#include "core/accuracy/accuracy_scene.h"

namespace lamina::core {

struct BarVerdict {
  std::string scene;
  std::string text;
  BarCheck check;
  bool known_failure = false;  ///< the bar's mark (AccuracyBar::known_failure)
};

/// Every bar of every scene that has runs in `runs`, judged on the default solver's runs.
std::vector<BarVerdict> JudgeAccuracyBars(const std::vector<AccuracyRun>& runs);

/// One row per run; metrics as "name=value" pairs separated by ';' in one column.
std::string AccuracyCsv(const std::vector<AccuracyRun>& runs);
/// {"runs": [...], "bars": [...]}.
std::string AccuracyJson(const std::vector<AccuracyRun>& runs, const std::vector<BarVerdict>& bars);
/// Appends the runs of an AccuracyJson text (`source` names it in messages) to `runs`; on bad
/// JSON, a missing or mistyped field, an unknown scene or solver label, nothing is appended and
/// `error` says what and where ("peers.json: runs[3].solver: ..."). A null number reads as NaN.
bool ReadAccuracyRunsJson(const std::string& text, const std::string& source,
                          std::vector<AccuracyRun>* runs, std::string* error);

enum class PlotAxis { kCpuTime, kStep };
/// The scene's error against CPU time or against the step, one series per solver.
std::string AccuracySceneSvg(const AccuracyScene& scene, const std::vector<AccuracyRun>& runs,
                             PlotAxis axis);
/// File name of that plot: "<scene>-time.svg" or "<scene>-step.svg".
std::string AccuracyPlotName(const AccuracyScene& scene, PlotAxis axis);

struct MarkdownContext {
  std::string plots_dir;  ///< relative to the Markdown file, e.g. "accuracy"
  std::string command;    ///< the command that produced it
  std::string machine;    ///< e.g. "2 cores, Intel Xeon ..., 2 runs at a time"
  std::string date;       ///< UTC date of the run
};
std::string AccuracyMarkdown(const std::vector<AccuracyRun>& runs,
                             const std::vector<BarVerdict>& bars, const MarkdownContext& context);

}  // namespace lamina::core
