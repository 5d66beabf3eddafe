// SPDX-License-Identifier: MIT
#include "core/accuracy/accuracy_report.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/accuracy/accuracy_run.h"
#include "core/accuracy/probe_support.h"
#include "core/accuracy/svg_plot.h"
#include "core/json_values.h"

namespace lamina::core {
namespace {

std::string Num(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string MetricsText(const ProbeResult& result) {
  std::string text;
  for (const ProbeMetric& metric : result.metrics) {
    text += (text.empty() ? "" : ";") + metric.name + "=" + Num(metric.value);
  }
  return text;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::vector<AccuracySolver> SolversOf(const std::vector<AccuracyRun>& runs,
                                      const std::string& scene) {
  std::vector<AccuracySolver> solvers;
  for (const AccuracyRun& run : runs) {
    if (run.scene != scene) continue;
    bool seen = false;
    for (const AccuracySolver& s : solvers) seen = seen || s == run.solver;
    if (!seen) solvers.push_back(run.solver);
  }
  return solvers;
}

// The runs of one scene and solver that ran, in step order.
std::vector<const AccuracyRun*> SeriesRuns(const std::vector<AccuracyRun>& runs,
                                           const std::string& scene, const AccuracySolver& solver) {
  std::vector<const AccuracyRun*> series;
  for (const AccuracyRun& run : runs) {
    if (run.scene == scene && run.solver == solver && run.failure.empty()) series.push_back(&run);
  }
  std::sort(series.begin(), series.end(),
            [](const AccuracyRun* a, const AccuracyRun* b) { return a->step < b->step; });
  return series;
}

struct SeriesData {
  std::vector<double> step, time, error;
};

SeriesData Data(const std::vector<const AccuracyRun*>& series) {
  SeriesData data;
  for (const AccuracyRun* run : series) {
    data.step.push_back(run->step);
    data.time.push_back(run->cpu_seconds);
    data.error.push_back(run->result.error);
  }
  return data;
}

std::string SlopeText(double slope) {
  // + 0.0: a slope that rounds to -0 prints as 0
  return std::isfinite(slope) ? Num(std::round(slope * 100) / 100 + 0.0) : "–";
}

// Bars judge Lamina's runs: a scene only another engine ran has none to judge.
bool HasLaminaRuns(const std::vector<AccuracyRun>& runs, const std::string& scene) {
  for (const AccuracySolver& solver : SolversOf(runs, scene)) {
    if (solver.peer.empty()) return true;
  }
  return false;
}

}  // namespace

std::vector<BarVerdict> JudgeAccuracyBars(const std::vector<AccuracyRun>& runs) {
  std::vector<BarVerdict> verdicts;
  for (const AccuracyScene& scene : AccuracyScenes()) {
    if (!HasLaminaRuns(runs, scene.name)) continue;
    for (const AccuracyBar& bar : scene.bars) {
      const auto found = FindAccuracyRuns(runs, scene.name, bar.solver, bar.steps);
      verdicts.push_back({scene.name, bar.text, bar.check(found), bar.known_failure});
    }
  }
  return verdicts;
}

std::string AccuracyCsv(const std::vector<AccuracyRun>& runs) {
  std::string csv =
      "scene,solver,step,error,cpu_s,real_time_factor,steps,rollbacks,min_step,corrections,"
      "nonfinite,unreliable,status,failure,note,metrics\n";
  for (const AccuracyRun& r : runs) {
    csv += r.scene + "," + r.solver.Label() + "," + Num(r.step) + "," + Num(r.result.error) + "," +
           Num(r.cpu_seconds) + "," + Num(r.real_time_factor) + "," + std::to_string(r.steps) +
           "," + std::to_string(r.rollbacks) + "," + Num(r.min_step) + "," +
           std::to_string(r.corrections) + "," + std::to_string(r.nonfinite) + "," +
           std::to_string(r.unreliable) + "," + CsvField(r.status) + "," + CsvField(r.failure) +
           "," + CsvField(r.result.note) + "," + CsvField(MetricsText(r.result)) + "\n";
  }
  return csv;
}

namespace {

nlohmann::json RunJson(const AccuracyRun& r) {
  nlohmann::json metrics = nlohmann::json::object();
  for (const ProbeMetric& m : r.result.metrics) metrics[m.name] = FiniteOrNull(m.value);
  return {{"scene", r.scene},         {"solver", r.solver.Label()},
          {"step", r.step},           {"error", FiniteOrNull(r.result.error)},
          {"cpu_s", r.cpu_seconds},   {"real_time_factor", FiniteOrNull(r.real_time_factor)},
          {"steps", r.steps},         {"rollbacks", r.rollbacks},
          {"min_step", r.min_step},   {"corrections", r.corrections},
          {"nonfinite", r.nonfinite}, {"unreliable", r.unreliable},
          {"status", r.status},       {"failure", r.failure},
          {"note", r.result.note},    {"metrics", metrics}};
}

}  // namespace

namespace {

double ReadNumber(const nlohmann::json& value) {
  return value.is_null() ? std::nan("") : value.get<double>();
}

// One entry of "runs"; throws nlohmann's type errors and std::invalid_argument with the field.
AccuracyRun ReadRun(const nlohmann::json& j) {
  AccuracyRun r;
  r.scene = j.at("scene").get<std::string>();
  if (FindAccuracyScene(r.scene) == nullptr)
    throw std::invalid_argument("scene: no scene '" + r.scene + "'");
  const std::string label = j.at("solver").get<std::string>();
  const std::optional<AccuracySolver> solver = ParseAccuracySolver(label);
  if (!solver) throw std::invalid_argument("solver: '" + label + "' names no solver");
  r.solver = *solver;
  r.step = j.at("step").get<double>();
  r.result.error = ReadNumber(j.at("error"));
  r.cpu_seconds = j.at("cpu_s").get<double>();
  r.real_time_factor = ReadNumber(j.at("real_time_factor"));
  r.steps = j.at("steps").get<long>();
  r.rollbacks = j.at("rollbacks").get<long>();
  r.min_step = j.at("min_step").get<double>();
  r.corrections = j.at("corrections").get<long>();
  r.nonfinite = j.at("nonfinite").get<long>();
  r.unreliable = j.at("unreliable").get<long>();
  r.status = j.at("status").get<std::string>();
  r.failure = j.at("failure").get<std::string>();
  r.result.note = j.at("note").get<std::string>();
  for (const auto& [name, value] : j.at("metrics").items())
    r.result.metrics.push_back({name, ReadNumber(value)});
  return r;
}

}  // namespace

bool ReadAccuracyRunsJson(const std::string& text, const std::string& source,
                          std::vector<AccuracyRun>* runs, std::string* error) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object() || !json.contains("runs") ||
      !json["runs"].is_array()) {
    *error = source + ": not JSON with a \"runs\" array";
    return false;
  }
  std::vector<AccuracyRun> read;
  for (std::size_t i = 0; i < json["runs"].size(); ++i) {
    try {
      read.push_back(ReadRun(json["runs"][i]));
    } catch (const std::exception& e) {
      *error = source + ": runs[" + std::to_string(i) + "]: " + e.what();
      return false;
    }
  }
  runs->insert(runs->end(), read.begin(), read.end());
  return true;
}

std::string AccuracyJson(const std::vector<AccuracyRun>& runs,
                         const std::vector<BarVerdict>& bars) {
  nlohmann::json json = {{"runs", nlohmann::json::array()}, {"bars", nlohmann::json::array()}};
  for (const AccuracyRun& run : runs) json["runs"].push_back(RunJson(run));
  for (const BarVerdict& bar : bars) {
    json["bars"].push_back({{"scene", bar.scene},
                            {"bar", bar.text},
                            {"pass", bar.check.pass},
                            {"measured", bar.check.measured},
                            {"known_failure", bar.known_failure}});
  }
  return json.dump(2) + "\n";
}

std::string AccuracyPlotName(const AccuracyScene& scene, PlotAxis axis) {
  return scene.name + (axis == PlotAxis::kCpuTime ? "-time.svg" : "-step.svg");
}

std::string AccuracySceneSvg(const AccuracyScene& scene, const std::vector<AccuracyRun>& runs,
                             PlotAxis axis) {
  LogLogPlot plot;
  plot.title = scene.title;
  plot.x_label = axis == PlotAxis::kCpuTime ? "CPU time of the run (s)" : "largest step h (s)";
  plot.y_label = scene.unit.empty() ? "relative error" : "error (" + scene.unit + ")";
  for (const AccuracySolver& solver : SolversOf(runs, scene.name)) {
    const SeriesData data = Data(SeriesRuns(runs, scene.name, solver));
    const std::vector<double>& x = axis == PlotAxis::kCpuTime ? data.time : data.step;
    const double slope = LogLogSlope(x, data.error);
    plot.series.push_back({solver.Label() + " (slope " + SlopeText(slope) + ")", x, data.error,
                           !solver.peer.empty()});
  }
  return LogLogSvg(plot);
}

namespace {

std::string BarTable(const std::vector<BarVerdict>& bars) {
  std::string md = "| scene | bar | measured | met |\n|---|---|---|---|\n";
  for (const BarVerdict& bar : bars) {
    const char* met = bar.check.pass
                          ? (bar.known_failure ? "yes (marked as a known failure)" : "yes")
                          : (bar.known_failure ? "**no** (known failure)" : "**no**");
    md += "| " + bar.scene + " | " + bar.text + " | " + bar.check.measured + " | " + met + " |\n";
  }
  return md;
}

const AccuracyRun* RunAt(const std::vector<const AccuracyRun*>& series, double step) {
  for (const AccuracyRun* run : series) {
    if (std::abs(run->step - step) <= 1e-12 * step) return run;
  }
  return nullptr;
}

std::string At1ms(const AccuracyRun* run, const std::string& unit) {
  if (run == nullptr) return "– | – ";
  return Measured(run->result.error, unit) + " | " +
         Num(std::round(run->real_time_factor * 10) / 10) + "× ";
}

std::string SolverTable(const AccuracyScene& scene, const std::vector<AccuracyRun>& runs) {
  std::string md =
      "| solver | order (slope against h) | slope against CPU time | error at 1 ms | real time "
      "at 1 ms | rollbacks | flagged runs |\n|---|---|---|---|---|---|---|\n";
  for (const AccuracySolver& solver : SolversOf(runs, scene.name)) {
    const auto series = SeriesRuns(runs, scene.name, solver);
    const SeriesData data = Data(series);
    long rollbacks = 0, flagged = 0;
    for (const AccuracyRun* run : series) {
      rollbacks += run->rollbacks;
      flagged += run->status != "normal" && run->status != "adaptive step";
    }
    md += "| " + solver.Label() + " | " + SlopeText(LogLogSlope(data.step, data.error)) + " | " +
          SlopeText(LogLogSlope(data.time, data.error)) + " | " +
          At1ms(RunAt(series, 1e-3), scene.unit) + "| " + std::to_string(rollbacks) + " | " +
          std::to_string(flagged) + " |\n";
  }
  return md;
}

std::string SceneSection(const AccuracyScene& scene, const std::vector<AccuracyRun>& runs,
                         const MarkdownContext& context) {
  std::string md = "### " + scene.title + " (`" + scene.name + "`)\n\n";
  md += "World `worlds/accuracy/" + scene.world + "`: " + scene.setup + ".\n\n";
  md += "- Error: " + scene.metric + " (" + scene.unit + ").\n";
  md += "- Answer: " + scene.answer + ".\n\n";
  for (PlotAxis axis : {PlotAxis::kCpuTime, PlotAxis::kStep}) {
    md +=
        "![" + scene.name + "](" + context.plots_dir + "/" + AccuracyPlotName(scene, axis) + ")\n";
  }
  return md + "\n" + SolverTable(scene, runs) + "\n";
}

std::string FailedRuns(const std::vector<AccuracyRun>& runs) {
  std::string md;
  for (const AccuracyRun& run : runs) {
    if (run.failure.empty() && run.status != "error" && run.nonfinite == 0) continue;
    md += "- " + run.scene + ", " + run.solver.Label() + ", h = " + Num(run.step) +
          " s: " + (run.failure.empty() ? run.status : run.failure) + "\n";
  }
  return md.empty() ? "None.\n" : md;
}

std::string Method() {
  return R"(
## Method

- **Runs.** Each scene runs for its stated time at each largest step h with each solver:
  `exact` is ODE's `dWorldStep` (a direct LCP solve), `newton` Lamina's Newton solver on the
  islands it takes (docs/simulator.md), `quickN` is `dWorldQuickStep` with N iterations; all use
  adaptive stepping (a step that goes wrong is rolled back and retaken at half the length) unless
  the label ends in `-fixed`. Scenes leave out steps below their stated smallest step where a run
  would take minutes.
- **Error.** Each scene's probe watches every accepted step and compares with the analytic answer
  computed from the world file (masses, friction, restitution, initial velocities), in physical
  units. The slope in the legends and tables is the least-squares slope of log(error) against
  log(h) (the order of convergence) or against log(CPU time) (negative: what time buys).
- **Time.** The CPU time of the stepping loop on the run's own thread
  (`CLOCK_THREAD_CPUTIME_ID`): loading and building are left out, and runs in parallel do not
  count each other's time. They still share the machine (caches, memory, the host under a
  virtual machine): on the project's 2-core virtual machine (2026-12-01) a run beside another
  took up to 70 % more CPU time than alone, so the first line says how many ran at a time, and
  `--threads 1` runs them one by one. Real time factor = simulated time / that CPU time.
- **Flags.** A run's status is the worst step status it saw (`adaptive step`, `contact
  unreliable`, `unstable`, `error`); rollbacks, the shortest step taken, instability corrections
  and non-finite states undone are in `runs.csv` and `runs.json`.
- **Bars.** Each scene states pass bars on its runs with the default solver (exact, adaptive).
  `make test` runs the same bars (tests/physics/accuracy_bars_test.cpp); the many-body scenes
  (pyramid_20, sphere_pile_666, kapla_102, bridge_160) only for their first 0.02 to 1 s there,
  and their known failures are judged here alone.
)";
}

std::string PeersMethod() {
  return R"(- **Peers** (dashed). `mujoco` and `bulletN` are other engines' runs, made by
  `make peers` (tests/bench/peers) with Debian 12's MuJoCo 2.2.2 and Bullet 3.24: MuJoCo with
  its defaults (semi-implicit Euler, Newton solver, pyramidal cone, soft contacts of time constant
  0.02 s, damping ratio 1) and Bullet in double precision (sequential impulse with N iterations,
  its other defaults), both at fixed steps. Each gets the scene's world with the boundary layer
  made solid (every shape grown by its padding) and every pair's blended friction and
  restitution (MuJoCo has no restitution: a pair with e > 0 gets the damping ratio of a
  spring–damper that rebounds with e). After each of its steps a Lamina simulation of the world
  is set to the engine's state, so the scene's own probe measures it. Their time is that of their
  step calls alone. Scenes with meshes or soft contact have no peer runs. Not judged by the bars.
)";
}

bool HasPeerRuns(const std::vector<AccuracyRun>& runs) {
  for (const AccuracyRun& run : runs) {
    if (!run.solver.peer.empty()) return true;
  }
  return false;
}

}  // namespace

std::string AccuracyMarkdown(const std::vector<AccuracyRun>& runs,
                             const std::vector<BarVerdict>& bars, const MarkdownContext& context) {
  std::string md = "# Accuracy: error against run time\n\n";
  md += "<!-- Generated by `" + context.command + "`; do not edit by hand. -->\n\n";
  md += "Measured " + context.date + " on " + context.machine + ", by `" + context.command +
        "` (the method is at the end of this page). Every scene is a world of "
        "`worlds/accuracy/` that the editor opens; its error is measured against an analytic "
        "answer. Times are the CPU time of the stepping loop of each run on its own thread.\n\n";
  md += "## Bars\n\n" + BarTable(bars) + "\n## Scenes\n\n";
  for (const AccuracyScene& scene : AccuracyScenes()) {
    if (!SolversOf(runs, scene.name).empty()) md += SceneSection(scene, runs, context);
  }
  return md + "## Runs that failed or lost their state\n\n" + FailedRuns(runs) + Method() +
         (HasPeerRuns(runs) ? PeersMethod() : "");
}

}  // namespace lamina::core
