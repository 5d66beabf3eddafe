// SPDX-License-Identifier: MIT
#include "core/batch/batch_spec.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/diagnostics.h"
#include "core/io/load_context.h"
#include "core/io/trajectory_file.h"
#include "core/io/world_file.h"
#include "core/model/access_path.h"
#include "core/suggest.h"

namespace lamina::core {

namespace {

using Json = nlohmann::ordered_json;

// a problem in the spec at `key` (the message gets the file name in front)
struct SpecError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void Fail(const std::string& key, const std::string& message) {
  throw SpecError(key + ": " + message);
}

std::string Member(const std::string& key, const std::string& name) {
  return key + "[\"" + name + "\"]";
}

std::string Element(const std::string& key, size_t i) {
  return key + "[" + std::to_string(i) + "]";
}

bool ReadText(const std::string& path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *text = buffer.str();
  return true;
}

// FNV-1a, 64 bits, as 16 hex digits
std::string Hash(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  char buffer[17];
  std::snprintf(buffer, sizeof(buffer), "%016llx", static_cast<unsigned long long>(h));
  return buffer;
}

void CheckKeys(const Json& object, const std::string& key, const std::vector<std::string>& known) {
  for (const auto& [name, value] : object.items()) {
    bool found = false;
    for (const std::string& k : known) found = found || k == name;
    if (found) continue;
    const std::string suggestion = SuggestName(name, known);
    Fail(key.empty() ? "\"" + name + "\"" : Member(key, name),
         "unknown key" + (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)"));
  }
}

double Number(const Json& json, const std::string& key) {
  if (!json.is_number()) Fail(key, "must be a number, got " + json.dump());
  const double v = json.get<double>();
  if (!std::isfinite(v)) Fail(key, "must be finite");
  return v;
}

double Positive(const Json& json, const std::string& key) {
  const double v = Number(json, key);
  if (!(v > 0)) Fail(key, "must be > 0, got " + json.dump());
  return v;
}

std::vector<double> Vector(const Json& json, const std::string& key) {
  if (json.is_number()) return {Number(json, key)};
  if (!json.is_array()) Fail(key, "must be a number or an array of numbers, got " + json.dump());
  std::vector<double> values;
  for (size_t i = 0; i < json.size(); ++i) values.push_back(Number(json[i], Element(key, i)));
  return values;
}

std::vector<std::vector<double>> Vectors(const Json& json, const std::string& key,
                                         const char* kind) {
  if (!json.is_array() || json.empty()) {
    Fail(key, std::string(kind) + " needs a non-empty array of values");
  }
  std::vector<std::vector<double>> values;
  for (size_t i = 0; i < json.size(); ++i) values.push_back(Vector(json[i], Element(key, i)));
  return values;
}

Sampler ReadSampler(const Json& json, const std::string& key, int runs) {
  Sampler sampler;
  if (json.is_number() || json.is_array()) {
    sampler = FixedSampler(Vector(json, key));
  } else if (!json.is_object() || json.size() != 1) {
    Fail(key,
         "must be a value or one of {\"uniform\": [lo, hi]}, {\"normal\": [mean, std]}, "
         "{\"choice\": [...]}, {\"list\": [...]}");
  } else {
    const std::string kind = json.begin().key();
    const Json& body = json.begin().value();
    if (kind == "uniform" || kind == "normal") {
      const char* form = kind == "uniform" ? "[lo, hi]" : "[mean, std]";
      if (!body.is_array() || body.size() != 2) Fail(key, kind + " needs " + form);
      std::vector<double> a = Vector(body[0], Element(Member(key, kind), 0));
      std::vector<double> b = Vector(body[1], Element(Member(key, kind), 1));
      sampler = kind == "uniform" ? UniformSampler(a, b) : NormalSampler(a, b);
    } else if (kind == "choice" || kind == "list") {
      std::vector<std::vector<double>> values = Vectors(body, Member(key, kind), kind.c_str());
      sampler = kind == "choice" ? ChoiceSampler(values) : ListSampler(values);
    } else {
      const std::string suggestion = SuggestName(kind, {"uniform", "normal", "choice", "list"});
      Fail(Member(key, kind),
           "unknown sampler" + (suggestion.empty()
                                    ? std::string(" (uniform, normal, choice or list)")
                                    : " (did you mean '" + suggestion + "'?)"));
    }
  }
  if (auto problem = sampler.Check(runs)) Fail(key, *problem);
  return sampler;
}

bool IsScalar(const AccessTarget& target) {
  if (target.component >= 0 || target.state == StateItem::kTime) return true;
  if (target.state != StateItem::kNone) return false;
  switch (target.row->type) {
    case ParamType::kReal:
    case ParamType::kInteger:
    case ParamType::kBool:
    case ParamType::kChoice:
      return true;
    default:
      return false;
  }
}

AccessTarget Resolve(const WorldDesc& world, const std::string& path, AccessContext context,
                     const std::string& key) {
  std::string error;
  std::optional<AccessTarget> target = ResolveAccessPath(world, path, context, &error);
  if (!target) Fail(key, error);
  return *target;
}

int ValueSize(const WorldDesc& world, const AccessTarget& target) {
  return target.component >= 0 ? 1 : AccessValueSize(world, target);
}

// the values a sampler can give that the table must accept (uniform: both ends)
std::vector<std::vector<double>> Extremes(const Sampler& sampler) {
  switch (sampler.kind) {
    case Sampler::Kind::kFixed:
      return {sampler.a};
    case Sampler::Kind::kUniform:
      return {sampler.a, sampler.b};
    case Sampler::Kind::kNormal:
      return {sampler.a};
    default:
      return sampler.options;
  }
}

class SpecReader {
 public:
  SpecReader(const Json& json, std::string path, BatchSpec* spec)
      : json_(json), path_(std::move(path)), spec_(spec) {}

  void Read() {
    CheckKeys(json_, "",
              {"world", "duration", "simDt", "N", "seed", "samplers", "set", "args", "setup",
               "terminate", "return", "trace"});
    ReadHeader();
    LoadWorld();
    if (json_.contains("set")) ReadSet(json_["set"]);
    if (json_.contains("samplers")) ReadSamplers(json_["samplers"]);
    if (json_.contains("args")) ReadArgs(json_["args"]);
    if (json_.contains("setup")) ReadSetup(json_["setup"]);
    if (json_.contains("terminate")) ReadTerminate(json_["terminate"]);
    ReadReturn();
    if (json_.contains("trace")) ReadTrace(json_["trace"]);
  }

 private:
  std::string Relative(const std::string& file) const {
    const std::filesystem::path p(file);
    if (p.is_absolute()) return file;
    return (std::filesystem::path(path_).parent_path() / p).lexically_normal().string();
  }

  void ReadHeader() {
    if (!json_.contains("world") || !json_["world"].is_string()) {
      Fail("world", "required: the world file (relative to the spec)");
    }
    if (!json_.contains("duration")) Fail("duration", "required: simulated seconds per run");
    spec_->plan.duration = Positive(json_["duration"], "duration");
    if (json_.contains("simDt")) spec_->plan.sim_dt = Positive(json_["simDt"], "simDt");
    if (json_.contains("N")) {
      const Json& n = json_["N"];
      if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 100000000) {
        Fail("N", "must be a whole number in [1, 1e8], got " + n.dump());
      }
      spec_->runs = n.get<int>();
    }
    if (json_.contains("seed")) {
      const Json& seed = json_["seed"];
      if (!seed.is_number_unsigned() && !(seed.is_number_integer() && seed.get<long long>() >= 0)) {
        Fail("seed", "must be a whole number >= 0, got " + seed.dump());
      }
      spec_->seed = seed.get<std::uint64_t>();
    }
  }

  void LoadWorld() {
    spec_->world_file = Relative(json_["world"].get<std::string>());
    Diagnostics diagnostics;
    MeshCache meshes;
    LoadContext context{diagnostics, meshes};
    const bool ok = LoadWorldFile(spec_->world_file, context, &spec_->world);
    if (!ok || diagnostics.HasErrors()) {
      std::string text = diagnostics.FormatAll();
      while (!text.empty() && text.back() == '\n') text.pop_back();
      Fail("world", "cannot load " + spec_->world_file + (text.empty() ? "" : ":\n" + text));
    }
    if (!ReadText(spec_->world_file, &world_text_))
      Fail("world", "cannot read " + spec_->world_file);
  }

  void SetValue(const std::string& path, const std::vector<double>& value, const std::string& key) {
    std::string error;
    if (!SetPath(&spec_->world, path, value, &error)) Fail(key, error);
  }

  void ReadSet(const Json& set) {
    if (!set.is_object()) Fail("set", "must be an object: access path -> value");
    for (const auto& [path, value] : set.items()) {
      const std::string key = Member("set", path);
      const AccessTarget target = Resolve(spec_->world, path, AccessContext::kDescription, key);
      std::vector<double> numbers;
      if (value.is_string()) {
        std::string error;
        std::optional<ParamValue> parsed =
            ParseAccessValue(target, value.get<std::string>(), &error);
        if (!parsed) Fail(key, error);
        numbers = *parsed;
      } else {
        numbers = Vector(value, key);
      }
      SetValue(path, numbers, key);
    }
  }

  void ReadSamplers(const Json& samplers) {
    if (!samplers.is_object()) Fail("samplers", "must be an object: access path -> sampler");
    for (const auto& [path, value] : samplers.items()) {
      const std::string key = Member("samplers", path);
      const AccessTarget target = Resolve(spec_->world, path, AccessContext::kDescription, key);
      Sampler sampler = ReadSampler(value, key, spec_->runs);
      const int size = ValueSize(spec_->world, target);
      if (static_cast<int>(sampler.size()) != size) {
        Fail(key, "values have " + std::to_string(sampler.size()) + " number(s), " + path +
                      " has " + std::to_string(size));
      }
      for (const std::vector<double>& value_at_end : Extremes(sampler)) {
        WorldDesc copy = spec_->world;
        std::string error;
        if (!SetPath(&copy, target, value_at_end, &error)) Fail(key, error);
      }
      spec_->samplers.initial.push_back({path, sampler});
      spec_->sampled.push_back({path, size, IsScalar(target)});
    }
  }

  void ReadArgs(const Json& args) {
    if (!args.is_object()) Fail("args", "must be an object: name -> value or sampler");
    for (const auto& [name, value] : args.items()) {
      Sampler sampler = ReadSampler(value, Member("args", name), spec_->runs);
      const int size = static_cast<int>(sampler.size());
      spec_->samplers.args.push_back({name, sampler});
      spec_->sampled.push_back({"args." + name, size, size == 1});
    }
  }

  int ArgSize(const std::string& name, const std::string& key) const {
    for (const NamedSampler& arg : spec_->samplers.args) {
      if (arg.name == name) return static_cast<int>(arg.sampler.size());
    }
    std::vector<std::string> names;
    for (const NamedSampler& arg : spec_->samplers.args) names.push_back(arg.name);
    const std::string suggestion = SuggestName(name, names);
    Fail(key, "args." + name + ": no such argument in \"args\"" +
                  (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)"));
  }

  ValueSource Source(const Json& json, const std::string& key, int size) {
    ValueSource source;
    if (json.is_string()) {
      const std::string text = json.get<std::string>();
      if (text.rfind("args.", 0) != 0)
        Fail(key, "must be numbers or \"args.NAME\", got " + json.dump());
      source.arg = text.substr(5);
      const int arg_size = ArgSize(source.arg, key);
      if (arg_size != size) {
        Fail(key, text + " has " + std::to_string(arg_size) + " number(s), the robot " +
                      std::to_string(size) + " link(s)");
      }
      return source;
    }
    source.literal = Vector(json, key);
    if (static_cast<int>(source.literal.size()) != size) {
      Fail(key, "has " + std::to_string(source.literal.size()) + " number(s), the robot " +
                    std::to_string(size) + " link(s)");
    }
    return source;
  }

  void ReadGains(const Json& setup, const std::string& key, int robot) {
    const std::vector<std::pair<const char*, const char*>> gains = {
        {"kP", "servoP"}, {"kI", "servoI"}, {"kD", "servoD"}};
    const size_t drivers = spec_->world.robots[robot].drivers.size();
    for (const auto& [name, row] : gains) {
      if (!setup.contains(name)) continue;
      const std::string gain_key = Member(key, name);
      const std::vector<double> values = Vector(setup[name], gain_key);
      if (values.size() != drivers) {
        Fail(gain_key, "has " + std::to_string(values.size()) + " number(s), the robot " +
                           std::to_string(drivers) + " driver(s)");
      }
      for (size_t d = 0; d < drivers; ++d) {
        SetValue("robots[" + std::to_string(robot) + "].drivers[" + std::to_string(d) + "]." + row,
                 {values[d]}, Element(gain_key, d));
      }
    }
  }

  void ReadCommand(const Json& setup, const std::string& key, int robot) {
    int commands = 0;
    for (const char* name : {"pid", "milestones", "path"}) commands += setup.contains(name);
    if (commands > 1) Fail(key, "give one of pid, milestones and path");
    if (commands == 0) return;
    RobotCommand command;
    command.robot = robot;
    const int links = spec_->world.robots[robot].dof();
    if (setup.contains("pid")) {
      command.kind = RobotCommand::Kind::kPid;
      command.values.push_back(Source(setup["pid"], Member(key, "pid"), links));
    } else if (setup.contains("milestones")) {
      command.kind = RobotCommand::Kind::kMilestones;
      const Json& list = setup["milestones"];
      const std::string list_key = Member(key, "milestones");
      if (!list.is_array() || list.empty()) Fail(list_key, "needs a non-empty array of milestones");
      for (size_t i = 0; i < list.size(); ++i) {
        command.values.push_back(Source(list[i], Element(list_key, i), links));
      }
    } else {
      command.kind = RobotCommand::Kind::kMotion;
      const std::string path_key = Member(key, "path");
      if (!setup["path"].is_string()) Fail(path_key, "must be a motion file name");
      const std::string file = Relative(setup["path"].get<std::string>());
      Diagnostics diagnostics;
      std::optional<MilestoneSequence> motion = ReadMotionFile(file, diagnostics);
      if (!motion || diagnostics.HasErrors()) {
        Fail(path_key, "cannot read " + file + ": " + diagnostics.FormatAll());
      }
      command.motion = *motion;
    }
    spec_->plan.commands.push_back(command);
  }

  void ReadSetup(const Json& setup) {
    if (!setup.is_array()) Fail("setup", "must be an array of robot set-ups");
    for (size_t i = 0; i < setup.size(); ++i) {
      const std::string key = Element("setup", i);
      const Json& one = setup[i];
      if (!one.is_object()) Fail(key, "must be an object");
      CheckKeys(one, key, {"robot", "kP", "kI", "kD", "pid", "milestones", "path"});
      int robot = 0;
      if (one.contains("robot")) {
        if (!one["robot"].is_number_integer()) Fail(Member(key, "robot"), "must be a robot index");
        robot = one["robot"].get<int>();
      }
      if (robot < 0 || robot >= static_cast<int>(spec_->world.robots.size())) {
        Fail(Member(key, "robot"), "robots[" + std::to_string(robot) + "]: the world has " +
                                       std::to_string(spec_->world.robots.size()) + " robot(s)");
      }
      ReadGains(one, key, robot);
      ReadCommand(one, key, robot);
    }
  }

  void ReadTerminate(const Json& terminate) {
    if (!terminate.is_array()) Fail("terminate", "must be an array of conditions");
    for (size_t i = 0; i < terminate.size(); ++i) {
      const std::string key = Element("terminate", i);
      const Json& one = terminate[i];
      if (!one.is_object()) Fail(key, "must be an object");
      if (one.contains("time")) {
        CheckKeys(one, key, {"time"});
        spec_->plan.stop_time = Positive(one["time"], Member(key, "time"));
      } else if (one.contains("unstable")) {
        CheckKeys(one, key, {"unstable"});
        if (!one["unstable"].is_boolean()) Fail(Member(key, "unstable"), "must be true or false");
        spec_->plan.stop_on_unstable = one["unstable"].get<bool>();
      } else if (one.contains("path")) {
        CheckKeys(one, key, {"path", "above", "below"});
        ReadBound(one, key);
      } else {
        Fail(
            key,
            "must be {\"time\": t}, {\"unstable\": true} or {\"path\": P, \"above\"|\"below\": x}");
      }
    }
  }

  void ReadBound(const Json& one, const std::string& key) {
    Termination t;
    if (!one["path"].is_string()) Fail(Member(key, "path"), "must be an access path");
    t.path = one["path"].get<std::string>();
    const AccessTarget target =
        Resolve(spec_->world, t.path, AccessContext::kSimulation, Member(key, "path"));
    if (ValueSize(spec_->world, target) != 1) {
      Fail(Member(key, "path"), t.path + " has several numbers; select one with [k]");
    }
    if (one.contains("above") == one.contains("below")) Fail(key, "needs one of above and below");
    t.above = one.contains("above");
    t.bound = Number(one[t.above ? "above" : "below"], Member(key, t.above ? "above" : "below"));
    spec_->plan.terminate.push_back(t);
  }

  void ReadReturn() {
    std::vector<std::string> paths;
    if (json_.contains("return")) {
      const Json& items = json_["return"];
      if (!items.is_array()) Fail("return", "must be an array of access paths");
      for (size_t i = 0; i < items.size(); ++i) {
        if (!items[i].is_string()) Fail(Element("return", i), "must be an access path");
        paths.push_back(items[i].get<std::string>());
      }
    } else {
      paths = DefaultReturnItems(spec_->world);
    }
    for (size_t i = 0; i < paths.size(); ++i) {
      if (paths[i] == "time") {
        Fail(Element("return", i), "time is always in the results (the column `time`)");
      }
      const AccessTarget target =
          Resolve(spec_->world, paths[i], AccessContext::kSimulation, Element("return", i));
      spec_->items.push_back({paths[i], ValueSize(spec_->world, target), IsScalar(target)});
    }
    spec_->plan.return_items = paths;
  }

  void ReadTrace(const Json& trace) {
    if (trace.is_boolean()) {
      spec_->plan.trace_rate = trace.get<bool>() ? spec_->plan.sim_dt : 0.0;
      return;
    }
    if (!trace.is_object()) Fail("trace", "must be true, false or {\"rate\": s}");
    CheckKeys(trace, "trace", {"rate"});
    if (trace.contains("rate")) spec_->plan.trace_rate = Positive(trace["rate"], "trace[\"rate\"]");
  }

 public:
  std::string world_text_;

 private:
  const Json& json_;
  std::string path_;
  BatchSpec* spec_;
};

}  // namespace

BatchMeta BatchSpec::Meta() const {
  BatchMeta meta;
  meta.spec = std::filesystem::path(file).filename().string();
  meta.spec_hash = hash;
  meta.runs = runs;
  meta.seed = seed;
  return meta;
}

std::optional<BatchSpec> ParseBatchSpec(const std::string& text, const std::string& path,
                                        std::string* error) {
  const std::string name = std::filesystem::path(path).filename().string();
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::parse_error& e) {
    *error = name + ": not JSON: " + e.what();
    return std::nullopt;
  }
  if (!json.is_object()) {
    *error = name + ": must be a JSON object";
    return std::nullopt;
  }
  BatchSpec spec;
  spec.file = path;
  try {
    SpecReader reader(json, path, &spec);
    reader.Read();
    spec.hash = Hash(json.dump() + "\n" + reader.world_text_);
  } catch (const SpecError& e) {
    *error = name + ": " + e.what();
    return std::nullopt;
  } catch (const std::exception& e) {
    *error = name + ": " + e.what();
    return std::nullopt;
  }
  return spec;
}

std::optional<BatchSpec> LoadBatchSpec(const std::string& path, std::string* error) {
  std::string text;
  if (!ReadText(path, &text)) {
    *error = path + ": cannot read the spec file";
    return std::nullopt;
  }
  return ParseBatchSpec(text, path, error);
}

}  // namespace lamina::core
