// SPDX-License-Identifier: MIT
#include "core/accuracy/stress_report.h"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/json_values.h"

namespace lamina::core {
namespace {

std::string Num3(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string VerdictText(const StressRecord& r) {
  std::string text = StressVerdictName(r.verdict);
  if (r.verdict != r.expected)
    text += std::string(" (expected ") + StressVerdictName(r.expected) + ")";
  return text;
}

std::string MetricText(const StressRecord& r) {
  return r.unit.empty() ? Num3(r.metric) : Num3(r.metric) + " " + r.unit;
}

nlohmann::json RecordJson(const StressRecord& r) {
  nlohmann::json metrics = nlohmann::json::object();
  for (const ProbeMetric& m : r.probe.metrics) metrics[m.name] = FiniteOrNull(m.value);
  return {
      {"name", r.name},
      {"world", r.world},
      {"solver", r.solver},
      {"step", r.step},
      {"duration", r.duration},
      {"verdict", StressVerdictName(r.verdict)},
      {"expected", StressVerdictName(r.expected)},
      {"why", r.why},
      {"status", r.status},
      {"steps", r.steps},
      {"rollbacks", r.rollbacks},
      {"instability_corrections", r.corrections},
      {"nonfinite_recoveries", r.nonfinite},
      {"unreliable_steps", r.unreliable},
      {"joint_open_steps", r.joint_open},
      {"max_joint_gap", FiniteOrNull(r.max_joint_gap)},
      {"min_step", r.min_step},
      {"max_penetration", FiniteOrNull(r.max_penetration)},
      {"cpu_s", r.cpu_seconds},
      {"metric", {{"text", r.metric_text}, {"unit", r.unit}, {"value", FiniteOrNull(r.metric)}}},
      {"probe",
       {{"error", FiniteOrNull(r.probe.error)}, {"note", r.probe.note}, {"metrics", metrics}}},
      {"lost", r.lost},
      {"failure", r.failure}};
}

}  // namespace

std::string StressTable(const std::vector<StressRecord>& records) {
  char line[320];
  std::snprintf(line, sizeof line, "%-32s %-22s %-18s %6s %5s %5s %9s %9s %7s  %s\n", "case",
                "verdict", "status", "rollb", "corr", "nonf", "min h s", "overlap m", "cpu s",
                "metric");
  std::string text = line;
  for (const StressRecord& r : records) {
    std::snprintf(line, sizeof line, "%-32s %-22s %-18s %6ld %5ld %5ld %9.3g %9.3g %7.3f  %s\n",
                  r.name.c_str(), VerdictText(r).c_str(), r.status.c_str(), r.rollbacks,
                  r.corrections, r.nonfinite, r.min_step, r.max_penetration, r.cpu_seconds,
                  (MetricText(r) + "  " + r.metric_text).c_str());
    text += line;
  }
  for (const StressRecord& r : records) {
    if (r.verdict == StressVerdict::kStable) continue;
    text += r.name + ": " + StressVerdictName(r.verdict) + ": " + r.why;
    if (!r.lost.empty()) {
      text += " (lost:";
      for (const std::string& name : r.lost) text += " " + name;
      text += ")";
    }
    if (!r.failure.empty()) text += " — " + r.failure;
    text += "\n";
  }
  return text;
}

std::string StressJson(const std::vector<StressRecord>& records) {
  nlohmann::json json = {{"cases", nlohmann::json::array()}, {"failed", FailedCount(records)}};
  for (const StressRecord& r : records) json["cases"].push_back(RecordJson(r));
  return json.dump(2) + "\n";
}

std::string StressMarkdownTable(const std::vector<StressRecord>& records) {
  std::string md =
      "| case | verdict | worst status | rollbacks | corrections | non-finite | smallest step | "
      "deepest overlap | CPU | metric |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const StressRecord& r : records) {
    std::string verdict = VerdictText(r);
    for (std::size_t i = 0; i < r.lost.size(); ++i) verdict += (i ? ", " : "; lost: ") + r.lost[i];
    md += "| " + r.name + " | " + verdict + " | " + r.status + " | " + std::to_string(r.rollbacks) +
          " | " + std::to_string(r.corrections) + " | " + std::to_string(r.nonfinite) + " | " +
          Num3(r.min_step) + " s | " + Num3(r.max_penetration * 1e3) + " mm | " +
          Num3(r.cpu_seconds) + " s | " + r.metric_text + ": " + MetricText(r) + " |\n";
  }
  return md;
}

int FailedCount(const std::vector<StressRecord>& records) {
  int failed = 0;
  for (const StressRecord& r : records) failed += r.verdict == StressVerdict::kFailed ? 1 : 0;
  return failed;
}

}  // namespace lamina::core
