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

// `setup`: Lamina's robot commands sent before simInit (docs/python.md): dicts with "robot" and
// "milestones" (a list of configurations) or "pid" (a configuration).
std::vector<core::RobotCommand> SetupCommands(py::handle setup) {
  std::vector<core::RobotCommand> commands;
  if (setup.is_none()) return commands;
  for (py::handle entry : setup) {
    py::dict d = py::reinterpret_borrow<py::dict>(entry);
    core::RobotCommand command;
    command.robot = d.contains("robot") ? d["robot"].cast<int>() : 0;
    if (d.contains("milestones")) {
      command.kind = core::RobotCommand::Kind::kMilestones;
      for (py::handle q : d["milestones"]) command.values.push_back({Flatten(q), ""});
    } else if (d.contains("pid")) {
      command.kind = core::RobotCommand::Kind::kPid;
      command.values.push_back({Flatten(d["pid"]), ""});
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

// a dict {path: value} (Klamp't's initialCondition; 'args' apart) as core initial conditions,
// every path checked on the description first
core::InitialCondition ToInitial(const core::WorldDesc& world, py::handle condition,
                                 py::tuple* args) {
  core::InitialCondition initial;
  if (condition.is_none()) return initial;
  for (auto item : py::reinterpret_borrow<py::dict>(condition)) {
    const std::string path = item.first.cast<std::string>();
    if (path == "args") {
      if (args != nullptr) *args = py::tuple(py::reinterpret_borrow<py::object>(item.second));
      continue;
    }
    std::string error;
    if (!core::ResolveAccessPath(world, path, AccessContext::kDescription, &error)) {
      throw py::value_error("initialCondition: " + error);
    }
    initial.values.push_back({path, Flatten(item.second)});
  }
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
  const core::InitialCondition initial = ToInitial(*world.desc, initial_condition, &args);
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
    initial.push_back(ToInitial(*world.desc, condition, &args.back()));
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

py::list MonteCarloSim(const PyWorld& world, double duration, py::handle samplers, int runs,
                       py::handle return_items, py::handle trace, double sim_dt, py::object init,
                       py::object step, py::object term, py::handle setup, std::uint64_t seed,
                       int threads) {
  const Batch batch =
      MakeBatch(world, duration, return_items, trace, sim_dt, init, step, term, setup, threads);
  core::MonteCarloSamplers data;
  std::vector<std::pair<std::string, py::object>> callables;  // in order, with data's
  bool python_samplers = false;
  for (auto item : py::reinterpret_borrow<py::dict>(samplers)) {
    const std::string path = item.first.cast<std::string>();
    std::string error;
    if (!core::ResolveAccessPath(*world.desc, path, AccessContext::kDescription, &error)) {
      throw py::value_error("initialConditionSamplers: " + error);
    }
    py::object sampler = py::reinterpret_borrow<py::object>(item.second);
    if (py::isinstance<core::Sampler>(sampler)) {
      const core::Sampler& s = sampler.cast<const core::Sampler&>();
      if (auto problem = s.Check(runs)) throw py::value_error(path + ": " + *problem);
      data.initial.push_back({path, s});
    } else if (PyCallable_Check(sampler.ptr())) {
      python_samplers = true;
    } else {
      throw py::type_error(path + ": a sampler is a lamina.sim.batch sampler or a callable");
    }
    callables.emplace_back(path, sampler);
  }
  std::vector<core::RunResult> results;
  std::vector<py::dict> conditions;
  if (batch.callbacks || python_samplers) {
    for (int i = 0; i < runs; ++i) {
      core::RunRandom random(seed, static_cast<std::uint64_t>(i));
      core::InitialCondition initial;
      py::dict condition;
      for (const auto& [path, sampler] : callables) {
        std::vector<double> value = py::isinstance<core::Sampler>(sampler)
                                        ? sampler.cast<const core::Sampler&>().Draw(&random, i)
                                        : Flatten(sampler());
        condition[py::str(path)] =
            value.size() == 1 ? py::object(py::float_(value[0])) : py::object(ToList(value));
        initial.values.push_back({path, std::move(value)});
      }
      core::RunResult result = RunSerial(batch, initial, py::tuple(), i);
      results.push_back(std::move(result));
      conditions.push_back(condition);
    }
  } else {
    std::vector<int> indices(static_cast<size_t>(runs));
    for (int i = 0; i < runs; ++i) indices[static_cast<size_t>(i)] = i;
    {
      py::gil_scoped_release release;
      results = core::MonteCarloSim(*batch.world, batch.plan, data, seed, indices, {threads, {}});
    }
    for (const core::RunResult& result : results) {
      py::dict condition;
      for (size_t k = 0; k < data.initial.size() && k < result.sampled.size(); ++k) {
        const std::vector<double>& value = result.sampled[k];
        condition[py::str(data.initial[k].name)] =
            value.size() == 1 ? py::object(py::float_(value[0])) : py::object(ToList(value));
      }
      conditions.push_back(condition);
    }
  }
  py::list out;
  for (size_t i = 0; i < results.size(); ++i) {
    out.append(py::make_tuple(conditions[i], ResultToPy(batch, results[i])));
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
