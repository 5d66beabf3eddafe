// SPDX-License-Identifier: MIT
#include "core/batch/batch_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/number_text.h"

namespace lamina::core {

namespace {

using Json = nlohmann::ordered_json;

// ---- CSV --------------------------------------------------------------------------------

// a cell: quoted when it holds a comma, a quote or a line break
std::string CsvCell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// the cells of one group's value: empty when missing or of another size
void AppendCells(const ColumnGroup& group, const std::vector<double>* value,
                 std::vector<std::string>* cells) {
  const bool have = value != nullptr && static_cast<int>(value->size()) == group.size;
  for (int k = 0; k < group.size; ++k) cells->push_back(have ? FormatDouble((*value)[k]) : "");
}

std::string JoinRow(const std::vector<std::string>& cells) {
  std::string line;
  for (size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) line += ',';
    line += CsvCell(cells[i]);
  }
  return line + "\n";
}

// ---- JSON numbers: non-finite values as "inf", "-inf", "nan" ------------------------------

Json NumberJson(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}

Json ValueJson(const std::vector<double>& value, bool scalar) {
  if (scalar && value.size() == 1) return NumberJson(value[0]);
  Json array = Json::array();
  for (double v : value) array.push_back(NumberJson(v));
  return array;
}

double NumberOf(const Json& json) {
  if (json.is_number()) return json.get<double>();
  if (json.is_string()) {
    const std::string text = json.get<std::string>();
    if (text == "nan") return std::nan("");
    double v = 0;
    if (ParseDouble(text, &v)) return v;
  }
  throw std::invalid_argument("expected a number, got " + json.dump());
}

std::vector<double> ValuesOf(const Json& json) {
  if (!json.is_array()) return {NumberOf(json)};
  std::vector<double> value;
  for (const Json& v : json) value.push_back(NumberOf(v));
  return value;
}

Json GroupsJson(const std::vector<ColumnGroup>& groups) {
  Json array = Json::array();
  for (const ColumnGroup& g : groups) {
    array.push_back({{"name", g.name}, {"size", g.size}, {"scalar", g.scalar}});
  }
  return array;
}

std::vector<ColumnGroup> JsonGroups(const Json& json) {
  std::vector<ColumnGroup> groups;
  for (const Json& g : json) {
    groups.push_back(
        {g.at("name").get<std::string>(), g.at("size").get<int>(), g.at("scalar").get<bool>()});
  }
  return groups;
}

Json NamedValuesJson(const std::vector<ColumnGroup>& groups,
                     const std::vector<std::vector<double>>& values) {
  Json object = Json::object();
  for (size_t i = 0; i < groups.size() && i < values.size(); ++i) {
    object[groups[i].name] = ValueJson(values[i], groups[i].scalar);
  }
  return object;
}

std::vector<std::vector<double>> JsonNamedValues(const std::vector<ColumnGroup>& groups,
                                                 const Json& object) {
  std::vector<std::vector<double>> values;
  if (object.empty()) return values;
  for (const ColumnGroup& g : groups) values.push_back(ValuesOf(object.at(g.name)));
  return values;
}

Json RunJson(const BatchTable& table, const RunResult& run, const OutputOptions& options) {
  Json json = {{"index", run.index},
               {"sampled", NamedValuesJson(table.sampled, run.sampled)},
               {"items", NamedValuesJson(table.items, run.items)},
               {"status", run.status}};
  if (!run.error.empty()) json["error"] = run.error;
  json["stop"] = run.stop;
  json["time"] = NumberJson(run.time);
  if (options.wall_time) {
    json["wall_clock_time"] = run.wall_clock_time;
    json["build_wall_time"] = run.build_wall_time;
  }
  if (!run.trace_time.empty()) {
    Json trace = {{"time", Json::array()}};
    for (double t : run.trace_time) trace["time"].push_back(NumberJson(t));
    for (size_t i = 0; i < table.items.size(); ++i) {
      Json column = Json::array();
      for (const auto& sample : run.trace)
        column.push_back(ValueJson(sample[i], table.items[i].scalar));
      trace[table.items[i].name] = column;
    }
    json["trace"] = trace;
  }
  return json;
}

RunResult JsonRun(const BatchTable& table, const Json& json) {
  RunResult run;
  run.index = json.at("index").get<int>();
  run.sampled = JsonNamedValues(table.sampled, json.at("sampled"));
  run.items = JsonNamedValues(table.items, json.at("items"));
  run.status = json.at("status").get<std::string>();
  if (json.contains("error")) run.error = json["error"].get<std::string>();
  run.stop = json.at("stop").get<std::string>();
  run.time = NumberOf(json.at("time"));
  if (json.contains("wall_clock_time")) run.wall_clock_time = NumberOf(json["wall_clock_time"]);
  if (json.contains("build_wall_time")) run.build_wall_time = NumberOf(json["build_wall_time"]);
  if (json.contains("trace")) {
    const Json& trace = json["trace"];
    run.trace_time = ValuesOf(trace.at("time"));
    run.trace.resize(run.trace_time.size());
    for (const ColumnGroup& g : table.items) {
      const Json& column = trace.at(g.name);
      for (size_t s = 0; s < run.trace.size(); ++s) run.trace[s].push_back(ValuesOf(column.at(s)));
    }
  }
  return run;
}

Json MetaJson(const BatchMeta& meta) {
  Json json = {
      {"spec", meta.spec}, {"spec_hash", meta.spec_hash}, {"runs", meta.runs}, {"seed", meta.seed}};
  if (meta.part) {
    json["shard"] = {
        {"k", meta.shard.k}, {"n", meta.shard.n}, {"contiguous", meta.shard.contiguous}};
  }
  return json;
}

BatchMeta JsonMeta(const Json& json) {
  BatchMeta meta;
  meta.spec = json.at("spec").get<std::string>();
  meta.spec_hash = json.at("spec_hash").get<std::string>();
  meta.runs = json.at("runs").get<int>();
  meta.seed = json.at("seed").get<std::uint64_t>();
  meta.wall_time = json.value("wall_time", true);
  if (json.contains("shard")) {
    meta.part = true;
    meta.shard.k = json["shard"].at("k").get<int>();
    meta.shard.n = json["shard"].at("n").get<int>();
    meta.shard.contiguous = json["shard"].at("contiguous").get<bool>();
  }
  return meta;
}

std::string StatValue(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6g", v);
  return buffer;
}

// "2, 5, 8" (at most 5, then "...")
std::string IndexList(const std::vector<int>& indices) {
  std::string text;
  for (size_t i = 0; i < indices.size() && i < 5; ++i) {
    text += (i ? ", " : "") + std::to_string(indices[i]);
  }
  if (indices.size() > 5) text += ", ...";
  return text;
}

}  // namespace

std::vector<std::string> FlatNames(const std::vector<ColumnGroup>& groups) {
  std::vector<std::string> names;
  for (const ColumnGroup& g : groups) {
    if (g.scalar && g.size == 1) {
      names.push_back(g.name);
      continue;
    }
    for (int k = 0; k < g.size; ++k) names.push_back(g.name + "[" + std::to_string(k) + "]");
  }
  return names;
}

std::string CsvText(const BatchTable& table, const OutputOptions& options) {
  std::vector<std::string> header = {"index"};
  for (const auto& name : FlatNames(table.sampled)) header.push_back(name);
  for (const auto& name : FlatNames(table.items)) header.push_back(name);
  header.insert(header.end(), {"status", "time"});
  if (options.wall_time) header.push_back("wall_clock_time");
  std::string text = JoinRow(header);
  for (const RunResult& run : table.runs) {
    std::vector<std::string> cells = {std::to_string(run.index)};
    for (size_t i = 0; i < table.sampled.size(); ++i) {
      AppendCells(table.sampled[i], i < run.sampled.size() ? &run.sampled[i] : nullptr, &cells);
    }
    for (size_t i = 0; i < table.items.size(); ++i) {
      AppendCells(table.items[i], i < run.items.size() ? &run.items[i] : nullptr, &cells);
    }
    cells.push_back(run.status);
    cells.push_back(FormatDouble(run.time));
    if (options.wall_time) cells.push_back(FormatDouble(run.wall_clock_time));
    text += JoinRow(cells);
  }
  return text;
}

std::string JsonLinesText(const BatchTable& table, const BatchMeta& meta,
                          const OutputOptions& options) {
  Json header = MetaJson(meta);
  header["wall_time"] = options.wall_time;
  header["sampled"] = GroupsJson(table.sampled);
  header["items"] = GroupsJson(table.items);
  std::string text = Json{{"lamina_batch", header}}.dump() + "\n";
  for (const RunResult& run : table.runs) text += RunJson(table, run, options).dump() + "\n";
  return text;
}

std::optional<BatchTable> ReadJsonLines(const std::string& text, const std::string& name,
                                        BatchMeta* meta, std::string* error) {
  std::istringstream in(text);
  std::string line;
  int number = 0;
  BatchTable table;
  try {
    while (std::getline(in, line)) {
      ++number;
      if (line.empty()) continue;
      const Json json = Json::parse(line);
      if (number == 1) {
        if (!json.contains("lamina_batch")) {
          throw std::invalid_argument("not a batch result (no lamina_batch header)");
        }
        const Json& header = json["lamina_batch"];
        *meta = JsonMeta(header);
        table.sampled = JsonGroups(header.at("sampled"));
        table.items = JsonGroups(header.at("items"));
        continue;
      }
      table.runs.push_back(JsonRun(table, json));
    }
    if (number == 0) throw std::invalid_argument("empty file");
  } catch (const std::exception& e) {
    *error = name + ":" + std::to_string(number) + ": " + e.what();
    return std::nullopt;
  }
  return table;
}

double Quantile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return std::nan("");
  const double position = p * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return sorted[below] + (sorted[above] - sorted[below]) * fraction;
}

std::optional<std::vector<double>> ColumnValues(const BatchTable& table, const std::string& name) {
  int column = 0;
  for (size_t g = 0; g < table.items.size(); ++g) {
    const std::vector<std::string> names = FlatNames({table.items[g]});
    for (size_t k = 0; k < names.size(); ++k, ++column) {
      if (names[k] != name) continue;
      std::vector<double> values;
      for (const RunResult& run : table.runs) {
        if (run.status == "error" || g >= run.items.size() || k >= run.items[g].size()) continue;
        if (std::isfinite(run.items[g][k])) values.push_back(run.items[g][k]);
      }
      return values;
    }
  }
  return std::nullopt;
}

BatchSummary Summarize(const BatchTable& table) {
  BatchSummary summary;
  summary.runs = static_cast<int>(table.runs.size());
  for (const RunResult& run : table.runs) {
    auto it = std::find_if(summary.statuses.begin(), summary.statuses.end(),
                           [&](const auto& s) { return s.first == run.status; });
    if (it == summary.statuses.end()) {
      summary.statuses.push_back({run.status, 1});
    } else {
      ++it->second;
    }
  }
  for (const std::string& name : FlatNames(table.items)) {
    std::vector<double> values = *ColumnValues(table, name);
    ColumnSummary column;
    column.name = name;
    column.count = static_cast<int>(values.size());
    if (!values.empty()) {
      std::sort(values.begin(), values.end());
      double sum = 0;
      for (double v : values) sum += v;
      column.mean = sum / column.count;
      double squares = 0;
      for (double v : values) squares += (v - column.mean) * (v - column.mean);
      column.std = column.count > 1 ? std::sqrt(squares / (column.count - 1)) : 0.0;
      column.min = values.front();
      column.max = values.back();
      const double ps[5] = {0.05, 0.25, 0.5, 0.75, 0.95};
      for (int i = 0; i < 5; ++i) column.q[i] = Quantile(values, ps[i]);
    }
    summary.columns.push_back(column);
  }
  return summary;
}

std::string SummaryText(const BatchSummary& summary) {
  std::string text = "runs: " + std::to_string(summary.runs) + " (";
  for (size_t i = 0; i < summary.statuses.size(); ++i) {
    text += (i ? ", " : "") + std::to_string(summary.statuses[i].second) + " " +
            summary.statuses[i].first;
  }
  text += ")\n";
  size_t width = 6;
  for (const ColumnSummary& c : summary.columns) width = std::max(width, c.name.size());
  char line[512];
  std::snprintf(line, sizeof(line), "%-*s %5s %12s %12s %12s %12s %12s %12s %12s %12s %12s\n",
                static_cast<int>(width), "item", "n", "mean", "std", "min", "q5", "q25", "q50",
                "q75", "q95", "max");
  text += line;
  for (const ColumnSummary& c : summary.columns) {
    std::snprintf(line, sizeof(line), "%-*s %5d %12s %12s %12s %12s %12s %12s %12s %12s %12s\n",
                  static_cast<int>(width), c.name.c_str(), c.count, StatValue(c.mean).c_str(),
                  StatValue(c.std).c_str(), StatValue(c.min).c_str(), StatValue(c.q[0]).c_str(),
                  StatValue(c.q[1]).c_str(), StatValue(c.q[2]).c_str(), StatValue(c.q[3]).c_str(),
                  StatValue(c.q[4]).c_str(), StatValue(c.max).c_str());
    text += line;
  }
  return text;
}

std::string SummaryJson(const BatchSummary& summary, const BatchMeta& meta) {
  Json json = MetaJson(meta);
  Json statuses = Json::object();
  for (const auto& [status, count] : summary.statuses) statuses[status] = count;
  json["statuses"] = statuses;
  Json columns = Json::object();
  for (const ColumnSummary& c : summary.columns) {
    columns[c.name] = {{"n", c.count},
                       {"mean", NumberJson(c.mean)},
                       {"std", NumberJson(c.std)},
                       {"min", NumberJson(c.min)},
                       {"q5", NumberJson(c.q[0])},
                       {"q25", NumberJson(c.q[1])},
                       {"q50", NumberJson(c.q[2])},
                       {"q75", NumberJson(c.q[3])},
                       {"q95", NumberJson(c.q[4])},
                       {"max", NumberJson(c.max)}};
  }
  json["columns"] = columns;
  return json.dump(2) + "\n";
}

std::optional<BatchTable> MergeParts(const std::vector<std::pair<std::string, std::string>>& parts,
                                     BatchMeta* meta, std::string* error) {
  if (parts.empty()) {
    *error = "no parts to merge";
    return std::nullopt;
  }
  BatchTable merged;
  std::map<int, std::string> shard_files;
  for (size_t p = 0; p < parts.size(); ++p) {
    const std::string& name = parts[p].first;
    BatchMeta part_meta;
    std::optional<BatchTable> table = ReadJsonLines(parts[p].second, name, &part_meta, error);
    if (!table) return std::nullopt;
    if (!part_meta.part) {
      *error = name + ": not a shard's part (no shard in its header)";
      return std::nullopt;
    }
    if (p == 0) {
      *meta = part_meta;
      merged.sampled = table->sampled;
      merged.items = table->items;
    } else if (part_meta.spec_hash != meta->spec_hash || part_meta.runs != meta->runs ||
               part_meta.seed != meta->seed) {
      *error = name + ": from another batch than " + parts[0].first + " (spec " + part_meta.spec +
               " hash " + part_meta.spec_hash + ", " + std::to_string(part_meta.runs) +
               " runs; expected " + meta->spec + " hash " + meta->spec_hash + ", " +
               std::to_string(meta->runs) + " runs)";
      return std::nullopt;
    } else if (part_meta.wall_time != meta->wall_time) {
      *error = name + (part_meta.wall_time ? ": has" : ": has no") + " wall times, " +
               parts[0].first + (meta->wall_time ? " has" : " has none") +
               " (write every part with or every part without --no-wall-time)";
      return std::nullopt;
    } else if (part_meta.shard.n != meta->shard.n ||
               part_meta.shard.contiguous != meta->shard.contiguous) {
      *error = name + ": shard of " + std::to_string(part_meta.shard.n) + " parts, " +
               parts[0].first + " of " + std::to_string(meta->shard.n);
      return std::nullopt;
    }
    const int k = part_meta.shard.k;
    if (shard_files.count(k)) {
      *error = name + ": shard " + std::to_string(k) + " of " + std::to_string(meta->shard.n) +
               " given twice (also " + shard_files[k] + ")";
      return std::nullopt;
    }
    shard_files[k] = name;
    const std::vector<int> expected = ShardIndices(meta->runs, part_meta.shard);
    std::vector<int> got;
    for (const RunResult& run : table->runs) got.push_back(run.index);
    if (got != expected) {
      *error = name + ": holds " + std::to_string(got.size()) + " runs, shard " +
               std::to_string(k) + " of " + std::to_string(meta->shard.n) + " has " +
               std::to_string(expected.size()) + " (a truncated or edited part?)";
      return std::nullopt;
    }
    for (RunResult& run : table->runs) merged.runs.push_back(std::move(run));
  }
  for (int k = 0; k < meta->shard.n; ++k) {
    if (shard_files.count(k)) continue;
    Shard missing = meta->shard;
    missing.k = k;
    *error = "missing shard " + std::to_string(k) + " of " + std::to_string(meta->shard.n) +
             " (runs " + IndexList(ShardIndices(meta->runs, missing)) + ")";
    return std::nullopt;
  }
  std::sort(merged.runs.begin(), merged.runs.end(),
            [](const RunResult& a, const RunResult& b) { return a.index < b.index; });
  meta->part = false;
  meta->shard = Shard{};
  return merged;
}

bool WriteFileAtomic(const std::string& path, const std::string& text, std::string* error) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      *error = "cannot write " + temporary;
      std::remove(temporary.c_str());
      return false;
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    *error = "cannot rename " + temporary + " to " + path;
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}

}  // namespace lamina::core
