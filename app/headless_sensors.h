// SPDX-License-Identifier: MIT
// The sensor cameras of a `run`: when (and only when) the world has camera sensors, an OSMesa
// context and the renderer take their pictures inside the simulation's steps; with a folder,
// every picture is written there as `<robot>_<sensor>_<NNNN>.png` (colour) and
// `<robot>_<sensor>_<NNNN>_depth.pgm` (16-bit binary PGM, depth in millimetres, 65535 where
// nothing is nearer than zmax), NNNN the sample's number from 0.
#pragma once

#include <memory>
#include <string>

namespace lamina::core {
class Simulator;
}

namespace lamina::app {

class SensorCameras {
 public:
  SensorCameras();
  ~SensorCameras();
  /// Gives `simulator` (which must outlive this) its camera renderer when it has cameras, and
  /// with a non-empty `folder` (created if missing) writes their pictures. False with `*error`
  /// when the context cannot be made or the folder cannot be written.
  bool Open(core::Simulator* simulator, const std::string& folder, std::string* error);
  /// Pictures taken so far.
  int pictures() const;
  /// Files that could not be written (the first one's name in `first_failure`).
  int failures() const;
  const std::string& first_failure() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lamina::app
