// SPDX-License-Identifier: MIT
// One accuracy run through another engine (lamina-peers): the engine steps the scene's peer
// world at a fixed step, and after every step a Lamina Simulator of the same world is set to the
// engine's poses and velocities and told of the step (Simulator::MirrorStep), so that the
// scene's own probe measures the engine exactly as it measures Lamina.
//
// Timing: the CPU time of the engine's step calls alone (this thread); reading the state back and
// the probe are not timed. The peers take fixed steps: no rollback, no adaptive stepping.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/accuracy/accuracy_scene.h"
#include "tests/bench/peers/peer_world.h"

namespace lamina::peers {

/// An object's state as an engine reports it.
struct PeerState {
  Pose pose = Pose::Identity();  ///< object frame in the world
  core::Twist velocity;          ///< of the frame origin, and angular; world
};

/// After a step: every object's state, and the contacts.
struct PeerReadout {
  std::vector<PeerState> objects;  ///< by object index
  int contacts = 0;                ///< contact points the engine kept
  double deepest = 0.0;            ///< deepest penetration of the peer surfaces, m (>= 0)
};

class PeerEngine {
 public:
  virtual ~PeerEngine() = default;
  /// Builds `world` for steps of `step` s; false with `why`.
  virtual bool Build(const PeerWorld& world, double step, std::string* why) = 0;
  /// One step of the engine.
  virtual void Step() = 0;
  /// The state after the last step (may do work the timing leaves out).
  virtual void Read(PeerReadout* readout) = 0;
  /// What went wrong in the engine's own judgement ("" while nothing did): MuJoCo resets a
  /// simulation whose accelerations became bad, after which its states are no answer.
  virtual std::string Trouble() const { return ""; }
};

/// "mujoco" or "bullet" with `iterations`; nullptr for another name.
std::unique_ptr<PeerEngine> MakePeerEngine(const core::AccuracySolver& solver);

/// Runs `scene` (its world loaded from `worlds_dir`) through `solver`'s engine at `step`. A scene
/// the peers cannot express gives a run whose failure starts with "not expressed: ".
core::AccuracyRun RunPeerScene(const core::AccuracyScene& scene, const std::string& worlds_dir,
                               const core::AccuracySolver& solver, double step);

}  // namespace lamina::peers
