// SPDX-License-Identifier: MIT
// lamina.model.access (get_item, set_item) and lamina.sim.batch (doSim, batchSim,
// monteCarloSim): access paths (core/model/access_path.h, core/sim/sim_access.h) and the C++
// batch (core/batch/batch_sim.h). Without Python callbacks a batch runs on every core with the
// GIL released; with Python samplers or callbacks it runs serially, holding the GIL.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/python/bindings.h"
#include "core/batch/batch_sim.h"
#include "core/batch/batch_spec.h"
#include "core/batch/sampler.h"
#include "core/sim/sim_access.h"

namespace lamina::python {

namespace {

using core::AccessContext;
using core::AccessTarget;

// ---- access ---------------------------------------------------------------------------------

py::object GetItem(py::handle obj, const std::string& path) {
  std::string error;
  std::optional<AccessTarget> target;
  std::optional<core::ParamValue> value;
  if (py::isinstance<PySim>(obj)) {
    const core::Simulator& sim = obj.cast<const PySim&>().get();
    target = core::ResolveSimulationPath(sim, path, &error);
    if (target) value = core::GetPath(sim, *target, &error);
  } else if (py::isinstance<PyWorld>(obj)) {
    const core::WorldDesc& world = *obj.cast<const PyWorld&>().desc;
    target = core::ResolveAccessPath(world, path, AccessContext::kDescription, &error);
    if (target) value = core::GetPath(world, *target, &error);
  } else {
    throw py::type_error("get_item: expected a WorldModel or a Simulator");
  }
  if (!value) throw py::value_error(error);
  return AccessValueToPy(*target, *value);
}

void SetItem(py::handle obj, const std::string& path, py::handle value) {
  std::string error;
  const core::ParamValue v = py::isinstance<py::bool_>(value)
                                 ? core::ParamValue{value.cast<bool>() ? 1.0 : 0.0}
                                 : Flatten(value);
  bool ok = false;
  if (py::isinstance<PySim>(obj)) {
    ok = core::SetPath(&obj.cast<PySim&>().get(), path, v, &error);
  } else if (py::isinstance<PyWorld>(obj)) {
    ok = core::SetPath(obj.cast<PyWorld&>().desc.get(), path, v, &error);
  } else {
    throw py::type_error("set_item: expected a WorldModel or a Simulator");
  }
  if (!ok) throw py::value_error(error);
}

// ---- batch ----------------------------------------------------------------------------------

// Everything a batch call shares: the plan, the return items' targets and the Python callbacks.
struct Batch {
  const core::WorldDesc* world = nullptr;
  core::RunPlan plan;
  std::vector<AccessTarget> items;
  py::object init, step, term;
  bool callbacks = false;
  int threads = 0;
};

// a configuration of `setup`: numbers, or "args.NAME" for a named argument's value
core::ValueSource SetupValue(py::handle q) {
  if (!py::isinstance<py::str>(q)) return {Flatten(q), ""};
  const std::string text = q.cast<std::string>();
  if (text.rfind("args.", 0) != 0 || text.size() == 5) {
    throw py::value_error("setup: '" + text + "' is neither numbers nor \"args.NAME\"");
  }
  return {{}, text.substr(5)};
}

// `setup`: Lamina's robot commands sent before simInit (docs/python.md): dicts with "robot" and
// "milestones" (a list of configurations) or "pid" (a configuration); a configuration may be
// "args.NAME", a named argument of the run.
std::vector<core::RobotCommand> SetupCommands(py::handle setup) {
  std::vector<core::RobotCommand> commands;
  if (setup.is_none()) return commands;
  for (py::handle entry : setup) {
    py::dict d = py::reinterpret_borrow<py::dict>(entry);
    core::RobotCommand command;
    command.robot = d.contains("robot") ? d["robot"].cast<int>() : 0;
    if (d.contains("milestones")) {
      command.kind = core::RobotCommand::Kind::kMilestones;
      for (py::handle q : d["milestones"]) command.values.push_back(SetupValue(q));
    } else if (d.contains("pid")) {
      command.kind = core::RobotCommand::Kind::kPid;
      command.values.push_back(SetupValue(d["pid"]));
    } else {
      throw py::value_error("setup: each entry needs 'milestones' or 'pid'");
    }
    commands.push_back(std::move(command));
  }
  return commands;
}

Batch MakeBatch(const PyWorld& world, double duration, py::handle return_items, py::handle trace,
                double sim_dt, py::object init, py::object step, py::object term, py::handle setup,
                int threads) {
  Batch batch;
  batch.world = world.desc.get();
  batch.plan.duration = duration;
  batch.plan.sim_dt = sim_dt;
  if (!return_items.is_none()) {
    for (py::handle item : return_items)
      batch.plan.return_items.push_back(item.cast<std::string>());
  } else {
    batch.plan.return_items = core::DefaultReturnItems(*world.desc);
  }
  for (const std::string& item : batch.plan.return_items) {
    std::string error;
    auto target = core::ResolveAccessPath(*world.desc, item, AccessContext::kSimulation, &error);
    if (!target) throw py::value_error("returnItems: " + error);
    batch.items.push_back(*target);
  }
  if (py::isinstance<py::bool_>(trace)) {
    batch.plan.trace_rate = trace.cast<bool>() ? sim_dt : 0.0;
  } else if (!trace.is_none()) {
    batch.plan.trace_rate = trace.cast<double>();
  }
  batch.plan.commands = SetupCommands(setup);
  batch.init = std::move(init);
  batch.step = std::move(step);
  batch.term = std::move(term);
  batch.callbacks = !batch.init.is_none() || !batch.step.is_none() || !batch.term.is_none();
  batch.threads = threads;
  return batch;
}

// a value as Klamp't hands it to Python: a number, or a list
py::object ValueToPy(const std::vector<double>& value) {
  return value.size() == 1 ? py::object(py::float_(value[0])) : py::object(ToList(value));
}

// every "args.NAME" of the set-up names one of the arguments `names`
void CheckSetupArgs(const Batch& batch, const std::vector<std::string>& names) {
  for (const core::RobotCommand& command : batch.plan.commands) {
    for (const core::ValueSource& source : command.values) {
      bool found = source.arg.empty();
      for (const std::string& name : names) found |= name == source.arg;
      if (!found) throw py::value_error("setup: args." + source.arg + ": no such argument");
    }
  }
}

// initialCondition['args']: Klamp't's tuple for the callbacks, or Lamina's dict {name: value}
// (named arguments, usable in `setup` as "args.NAME" and given to the callbacks in order)
void ToArgs(py::handle value, core::InitialCondition* initial, py::tuple* args) {
  if (!py::isinstance<py::dict>(value)) {
    *args = py::tuple(py::reinterpret_borrow<py::object>(value));
    return;
  }
  py::list positional;
  for (auto item : py::reinterpret_borrow<py::dict>(value)) {
    initial->args.push_back({item.first.cast<std::string>(), Flatten(item.second)});
    positional.append(ValueToPy(initial->args.back().value));
  }
  *args = py::tuple(positional);
}

// a dict {path: value} (Klamp't's initialCondition; 'args' apart) as core initial conditions,
// every path checked on the description first
core::InitialCondition ToInitial(const Batch& batch, py::handle condition, py::tuple* args) {
  core::InitialCondition initial;
  if (!condition.is_none()) {
    for (auto item : py::reinterpret_borrow<py::dict>(condition)) {
      const std::string path = item.first.cast<std::string>();
      if (path == "args") {
        ToArgs(item.second, &initial, args);
        continue;
      }
      std::string error;
      if (!core::ResolveAccessPath(*batch.world, path, AccessContext::kDescription, &error)) {
        throw py::value_error("initialCondition: " + error);
      }
      initial.values.push_back({path, Flatten(item.second)});
    }
  }
  std::vector<std::string> names;
  for (const core::NamedValue& a : initial.args) names.push_back(a.name);
  CheckSetupArgs(batch, names);
  return initial;
}

py::dict ResultToPy(const Batch& batch, const core::RunResult& result) {
  py::dict out;
  const size_t n = batch.items.size();
  for (size_t i = 0; i < n; ++i) {
    const std::string& key = batch.plan.return_items[i];
    if (batch.plan.trace_rate > 0) {
      py::list values;
      for (const auto& sample : result.trace)
        values.append(AccessValueToPy(batch.items[i], sample[i]));
      out[py::str(key)] = values;
    } else if (i < result.items.size()) {
      out[py::str(key)] = AccessValueToPy(batch.items[i], result.items[i]);
    }
  }
  if (batch.plan.trace_rate > 0) out["trace_time"] = ToList(result.trace_time);
  out["status"] = result.status;
  if (!result.error.empty()) out["error"] = result.error;
  out["stop"] = result.stop;
  out["time"] = result.time;
  out["wall_clock_time"] = result.wall_clock_time;
  return out;
}

// one run holding the GIL, Python callbacks called as Klamp't does: f(sim, *args)
core::RunResult RunSerial(const Batch& batch, const core::InitialCondition& initial,
                          const py::tuple& args, int index) {
  core::RunPlan plan = batch.plan;
  std::shared_ptr<PySim> current;
  auto sim_of = [&](core::RunContext& context) {
    if (!current || current->sim != &context.simulator) {
      current = std::make_shared<PySim>();
      current->desc = std::make_shared<core::WorldDesc>(context.simulator.world());
      current->sim = &context.simulator;
    }
    return py::cast(current);
  };
  auto call = [&](const py::object& f, core::RunContext& context) {
    py::list call_args;
    call_args.append(sim_of(context));
    for (py::handle a : args) call_args.append(a);
    return f(*py::tuple(call_args));
  };
  if (!batch.init.is_none()) plan.hooks.init = [&](core::RunContext& c) { call(batch.init, c); };
  if (!batch.step.is_none()) plan.hooks.step = [&](core::RunContext& c) { call(batch.step, c); };
  if (!batch.term.is_none()) {
    plan.hooks.term = [&](core::RunContext& c) {
      py::object stop = call(batch.term, c);
      return stop.is(py::bool_(true));
    };
  }
  core::RunResult result = core::DoSim(*batch.world, plan, initial, index);
  if (current) current->sim = nullptr;
  return result;
}

py::dict DoSim(const PyWorld& world, double duration, py::handle initial_condition,
               py::handle return_items, py::handle trace, double sim_dt, py::object init,
               py::object step, py::object term, py::handle setup) {
  const Batch batch =
      MakeBatch(world, duration, return_items, trace, sim_dt, init, step, term, setup, 1);
  py::tuple args;
  const core::InitialCondition initial = ToInitial(batch, initial_condition, &args);
  if (batch.callbacks) return ResultToPy(batch, RunSerial(batch, initial, args, 0));
  core::RunResult result;
  {
    py::gil_scoped_release release;
    result = core::DoSim(*batch.world, batch.plan, initial, 0);
  }
  return ResultToPy(batch, result);
}

py::list BatchSim(const PyWorld& world, double duration, py::handle initial_conditions,
                  py::handle return_items, py::handle trace, double sim_dt, py::object init,
                  py::object step, py::object term, py::handle setup, int threads) {
  const Batch batch =
      MakeBatch(world, duration, return_items, trace, sim_dt, init, step, term, setup, threads);
  std::vector<core::InitialCondition> initial;
  std::vector<py::tuple> args;
  for (py::handle condition : initial_conditions) {
    args.emplace_back();
    initial.push_back(ToInitial(batch, condition, &args.back()));
  }
  std::vector<core::RunResult> results;
  if (batch.callbacks) {
    for (size_t i = 0; i < initial.size(); ++i) {
      results.push_back(RunSerial(batch, initial[i], args[i], static_cast<int>(i)));
    }
  } else {
    py::gil_scoped_release release;
    results = core::BatchSim(*batch.world, batch.plan, initial, {threads, {}});
  }
  py::list out;
  for (const core::RunResult& result : results) out.append(ResultToPy(batch, result));
  return out;
}

// monteCarloSim's samplers by kind: data samplers (lamina.sim.batch) for the C++ batch, Python
// callables, and the arguments — Klamp't's 'args' callable giving a tuple, or Lamina's dict
// {name: sampler} of named arguments (drawn after the initial conditions, as in a JSON spec)
struct PySamplers {
  std::vector<std::pair<std::string, py::object>> initial, named_args;
  py::object klampt_args = py::none();
  core::MonteCarloSamplers data;  ///< every data sampler, in drawing order
  bool python = false;            ///< some sampler is a Python callable
};

// `sampler` checked: a data sampler (added to `data` as `name`) or a callable (sets `python`);
// messages name it `label`
void Classify(const std::string& label, const std::string& name, const py::object& sampler,
              int runs, std::vector<core::NamedSampler>* data, bool* python) {
  if (py::isinstance<core::Sampler>(sampler)) {
    const core::Sampler& s = sampler.cast<const core::Sampler&>();
    if (auto problem = s.Check(runs)) throw py::value_error(label + ": " + *problem);
    data->push_back({name, s});
  } else if (PyCallable_Check(sampler.ptr())) {
    *python = true;
  } else {
    throw py::type_error(label + ": a sampler is a lamina.sim.batch sampler or a callable");
  }
}

PySamplers ReadSamplers(const core::WorldDesc& world, py::handle samplers, int runs) {
  PySamplers out;
  for (auto item : py::reinterpret_borrow<py::dict>(samplers)) {
    const std::string path = item.first.cast<std::string>();
    py::object sampler = py::reinterpret_borrow<py::object>(item.second);
    if (path == "args" && py::isinstance<py::dict>(sampler)) {
      for (auto arg : py::reinterpret_borrow<py::dict>(sampler)) {
        const std::string name = arg.first.cast<std::string>();
        py::object s = py::reinterpret_borrow<py::object>(arg.second);
        Classify("args." + name, name, s, runs, &out.data.args, &out.python);
        out.named_args.emplace_back(name, s);
      }
      continue;
    }
    if (path == "args") {
      if (!PyCallable_Check(sampler.ptr())) {
        throw py::type_error("args: a callable giving a tuple, or a dict {name: sampler}");
      }
      out.klampt_args = sampler;
      out.python = true;
      continue;
    }
    std::string error;
    if (!core::ResolveAccessPath(world, path, AccessContext::kDescription, &error)) {
      throw py::value_error("initialConditionSamplers: " + error);
    }
    Classify(path, path, sampler, runs, &out.data.initial, &out.python);
    out.initial.emplace_back(path, sampler);
  }
  return out;
}

std::vector<double> Draw(const py::object& sampler, core::RunRandom* random, int index) {
  if (py::isinstance<core::Sampler>(sampler)) {
    return sampler.cast<const core::Sampler&>().Draw(random, index);
  }
  return Flatten(sampler());
}

// run i of a serial batch: drawn as the C++ batch draws (initial conditions, then named args,
// from RunRandom(seed, i)), Python samplers called in their place
core::RunResult RunSampled(const Batch& batch, const PySamplers& samplers, std::uint64_t seed,
                           int i, py::dict* condition) {
  core::RunRandom random(seed, static_cast<std::uint64_t>(i));
  core::InitialCondition initial;
  for (const auto& [path, sampler] : samplers.initial) {
    initial.values.push_back({path, Draw(sampler, &random, i)});
    (*condition)[py::str(path)] = ValueToPy(initial.values.back().value);
  }
  py::list positional;
  py::dict named;
  for (const auto& [name, sampler] : samplers.named_args) {
    initial.args.push_back({name, Draw(sampler, &random, i)});
    named[py::str(name)] = ValueToPy(initial.args.back().value);
    positional.append(named[py::str(name)]);
  }
  py::tuple args(positional);
  if (!samplers.klampt_args.is_none()) args = py::tuple(samplers.klampt_args());
  if (!samplers.named_args.empty()) (*condition)["args"] = named;
  if (!samplers.klampt_args.is_none()) (*condition)["args"] = args;
  return RunSerial(batch, initial, args, i);
}

// a C++ run's sampled values as Klamp't's initial condition (named args under 'args')
py::dict SampledToPy(const core::MonteCarloSamplers& data, const core::RunResult& result) {
  py::dict condition, named;
  for (size_t k = 0; k < result.sampled.size(); ++k) {
    const bool is_arg = k >= data.initial.size();
    const std::string& name =
        is_arg ? data.args[k - data.initial.size()].name : data.initial[k].name;
    (is_arg ? named : condition)[py::str(name)] = ValueToPy(result.sampled[k]);
  }
  if (!data.args.empty()) condition["args"] = named;
  return condition;
}

py::list MonteCarloSim(const PyWorld& world, double duration, py::handle samplers, int runs,
                       py::handle return_items, py::handle trace, double sim_dt, py::object init,
                       py::object step, py::object term, py::handle setup, std::uint64_t seed,
                       int threads) {
  const Batch batch =
      MakeBatch(world, duration, return_items, trace, sim_dt, init, step, term, setup, threads);
  const PySamplers sampled = ReadSamplers(*world.desc, samplers, runs);
  std::vector<std::string> names;
  for (const auto& arg : sampled.named_args) names.push_back(arg.first);
  CheckSetupArgs(batch, names);
  py::list out;
  if (batch.callbacks || sampled.python) {
    for (int i = 0; i < runs; ++i) {
      py::dict condition;
      const core::RunResult result = RunSampled(batch, sampled, seed, i, &condition);
      out.append(py::make_tuple(condition, ResultToPy(batch, result)));
    }
    return out;
  }
  std::vector<int> indices(static_cast<size_t>(runs));
  for (int i = 0; i < runs; ++i) indices[static_cast<size_t>(i)] = i;
  std::vector<core::RunResult> results;
  {
    py::gil_scoped_release release;
    results =
        core::MonteCarloSim(*batch.world, batch.plan, sampled.data, seed, indices, {threads, {}});
  }
  for (const core::RunResult& result : results) {
    out.append(py::make_tuple(SampledToPy(sampled.data, result), ResultToPy(batch, result)));
  }
  return out;
}

// A JSON batch spec (docs/batch.md) run as `lamina-headless batch` runs it: (index, sampled,
// items, status) per run.
py::list RunSpec(const std::string& path, int threads) {
  std::string error;
  std::optional<core::BatchSpec> spec = core::LoadBatchSpec(path, &error);
  if (!spec) throw py::value_error(error);
  std::vector<int> indices(static_cast<size_t>(spec->runs));
  for (int i = 0; i < spec->runs; ++i) indices[static_cast<size_t>(i)] = i;
  std::vector<core::RunResult> results;
  {
    py::gil_scoped_release release;
    results = core::MonteCarloSim(spec->world, spec->plan, spec->samplers, spec->seed, indices,
                                  {threads, {}});
  }
  py::list out;
  for (const core::RunResult& r : results) {
    out.append(py::dict(py::arg("index") = r.index, py::arg("sampled") = r.sampled,
                        py::arg("items") = r.items, py::arg("status") = r.status,
                        py::arg("time") = r.time));
  }
  return out;
}

}  // namespace

void BindBatch(py::module_& m) {
  m.def("get_item", &GetItem, py::arg("obj"), py::arg("path"),
        "The value an access path names on a WorldModel or a Simulator.");
  m.def("set_item", &SetItem, py::arg("obj"), py::arg("path"), py::arg("value"),
        "Sets what an access path names, checked by the parameter table.");

  py::class_<core::Sampler>(m, "Sampler", "A sampler of a Monte-Carlo batch (data, no Python)")
      .def_static("fixed", [](py::handle v) { return core::FixedSampler(Flatten(v)); })
      .def_static("uniform",
                  [](py::handle lo, py::handle hi) {
                    return core::UniformSampler(Flatten(lo), Flatten(hi));
                  })
      .def_static("normal",
                  [](py::handle mean, py::handle std) {
                    return core::NormalSampler(Flatten(mean), Flatten(std));
                  })
      .def_static("choice",
                  [](py::handle options) {
                    std::vector<std::vector<double>> values;
                    for (py::handle o : options) values.push_back(Flatten(o));
                    return core::ChoiceSampler(std::move(values));
                  })
      .def_static("list", [](py::handle options) {
        std::vector<std::vector<double>> values;
        for (py::handle o : options) values.push_back(Flatten(o));
        return core::ListSampler(std::move(values));
      });

  const py::none none;
  m.def("doSim", &DoSim, py::arg("world"), py::arg("duration"), py::arg("initialCondition"),
        py::arg("returnItems") = none, py::arg("trace") = false, py::arg("simDt") = 0.01,
        py::arg("simInit") = none, py::arg("simStep") = none, py::arg("simTerm") = none,
        py::kw_only(), py::arg("setup") = none);
  m.def("batchSim", &BatchSim, py::arg("world"), py::arg("duration"), py::arg("initialConditions"),
        py::arg("returnItems") = none, py::arg("trace") = false, py::arg("simDt") = 0.01,
        py::arg("simInit") = none, py::arg("simStep") = none, py::arg("simTerm") = none,
        py::kw_only(), py::arg("setup") = none, py::arg("threads") = 0);
  m.def("monteCarloSim", &MonteCarloSim, py::arg("world"), py::arg("duration"),
        py::arg("initialConditionSamplers"), py::arg("N"), py::arg("returnItems") = none,
        py::arg("trace") = false, py::arg("simDt") = 0.01, py::arg("simInit") = none,
        py::arg("simStep") = none, py::arg("simTerm") = none, py::kw_only(),
        py::arg("setup") = none, py::arg("seed") = 0, py::arg("threads") = 0);
  m.def("runSpec", &RunSpec, py::arg("path"), py::arg("threads") = 0,
        "Runs a JSON batch spec (docs/batch.md) as lamina-headless batch does.");
}

}  // namespace lamina::python
