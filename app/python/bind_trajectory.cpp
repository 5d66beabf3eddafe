// SPDX-License-Identifier: MIT
// The file side of lamina.model.trajectory: Klamp't's `.path` text ("t  N q1 ... qN" per line)
// read and written by core/io's parser and writer, so a bad line raises with its file:line.
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/python/bindings.h"
#include "core/diagnostics.h"
#include "core/io/paths.h"
#include "core/io/trajectory_file.h"

namespace lamina::python {

namespace {

std::string Errors(const core::Diagnostics& diagnostics, const std::string& fallback) {
  std::string message;
  for (const std::string& line : diagnostics.Messages(core::Severity::kError)) {
    message += (message.empty() ? "" : "\n") + line;
  }
  return message.empty() ? fallback : message;
}

// (times, milestones) of a .path file
py::tuple ReadPath(const std::string& path) {
  std::string text;
  if (!core::ReadFileText(path, &text)) {
    throw std::runtime_error(path + ": cannot open the path file");
  }
  core::Diagnostics diagnostics;
  const auto sequence = core::ParseLinearPath(text, path, diagnostics);
  if (!sequence || diagnostics.HasErrors()) {
    throw std::runtime_error(Errors(diagnostics, path + ": not a path file"));
  }
  py::list milestones;
  for (const core::VecX& q : sequence->configs) milestones.append(ToList(q));
  return py::make_tuple(ToList(sequence->times), milestones);
}

void WritePath(const std::string& path, py::handle times, py::handle milestones) {
  core::MilestoneSequence sequence;
  sequence.times = Flatten(times);
  for (py::handle q : py::iter(milestones)) sequence.configs.push_back(ToVecX(q));
  if (sequence.times.size() != sequence.configs.size()) {
    throw py::value_error("save: " + std::to_string(sequence.times.size()) + " times for " +
                          std::to_string(sequence.configs.size()) + " milestones");
  }
  std::string error;
  if (!core::WriteFileAtomically(path, core::WriteLinearPath(sequence), &error)) {
    throw std::runtime_error(path + ": " + error);
  }
}

}  // namespace

void BindTrajectory(py::module_& m) {
  m.def("_read_path", &ReadPath, py::arg("fn"),
        "(times, milestones) of a Klamp't .path file; RuntimeError with file:line otherwise.");
  m.def("_write_path", &WritePath, py::arg("fn"), py::arg("times"), py::arg("milestones"),
        "Writes a Klamp't .path file (atomically).");
}

}  // namespace lamina::python
