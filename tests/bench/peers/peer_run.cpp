// SPDX-License-Identifier: MIT
#include "tests/bench/peers/peer_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/accuracy/probe_support.h"
#include "core/io/world_file.h"
#include "core/sim/simulator.h"

namespace lamina::peers {
namespace {

using core::AccuracyRun;

bool Finite(const PeerState& state) {
  return state.pose.matrix().allFinite() && state.velocity.linear.allFinite() &&
         state.velocity.angular.allFinite();
}

// Sets the mirror to the engine's state and tells it of the step; false when a state is not
// finite (the mirror keeps the last finite one).
bool Mirror(const PeerReadout& readout, double step, core::Simulator* mirror) {
  for (const PeerState& state : readout.objects) {
    if (!Finite(state)) return false;
  }
  for (std::size_t i = 0; i < readout.objects.size(); ++i) {
    mirror->SetObjectPose(static_cast<int>(i), readout.objects[i].pose);
    mirror->SetObjectVelocity(static_cast<int>(i), readout.objects[i].velocity);
  }
  // the engine's deepest penetration reaches the statistics as one pair of no bodies (a probe that
  // reads a body's own pairs, as the soft-layer scenes' do, finds none: those scenes have no peer
  // runs)
  std::vector<core::ContactPair> pairs(1);
  pairs[0].max_depth = readout.deepest;
  mirror->MirrorStep(step, readout.contacts, pairs);
  return true;
}

// How far the engine's state before any step is from the world's initial state (m, m/s, rad/s
// and rotation-matrix entries mixed: a check of the frame conversions, which must give ~1e-12).
double StartMismatch(const core::WorldDesc& world, const PeerReadout& readout) {
  double worst = readout.objects.size() == world.objects.size() ? 0.0 : 1.0;
  for (std::size_t i = 0; i < readout.objects.size() && i < world.objects.size(); ++i) {
    const core::RigidObjectDesc& object = world.objects[i];
    const PeerState& state = readout.objects[i];
    worst = std::max({worst, (state.pose.matrix() - object.pose.matrix()).cwiseAbs().maxCoeff(),
                      (state.velocity.linear - object.initial_velocity.linear).norm(),
                      (state.velocity.angular - object.initial_velocity.angular).norm()});
  }
  return worst;
}

long StepCount(const core::AccuracyScene& scene, double step) {
  return std::max(1L, std::lround(scene.duration / step));
}

// The probe's run: every step read back into the mirror.
void Measure(const core::AccuracyScene& scene, const core::WorldDesc& world, PeerEngine* engine,
             double step, AccuracyRun* run) {
  core::Simulator mirror(world);
  const std::unique_ptr<core::AccuracyProbe> probe = scene.probe(world);
  mirror.AddStepObserver([&](const core::StepEvent& event) { probe->Observe(event); });
  probe->Begin(mirror);
  PeerReadout readout;
  const long steps = StepCount(scene, step);
  for (long i = 0; i < steps; ++i) {
    engine->Step();
    if (const std::string trouble = engine->Trouble(); !trouble.empty()) {
      run->failure = trouble;
      run->status = "error";
      break;
    }
    engine->Read(&readout);
    if (!Mirror(readout, step, &mirror)) {
      run->failure = "a state became non-finite at t = " + std::to_string((i + 1) * step) + " s";
      run->nonfinite = 1;
      break;
    }
  }
  run->result = probe->Finish(mirror);
  run->steps = mirror.statistics().steps;
  run->min_step = step;
  if (run->status.empty()) run->status = "normal";
}

// The timed run: the same steps on a fresh build, nothing read back.
double TimeSteps(const core::AccuracyScene& scene, PeerEngine* engine, double step) {
  const long steps = StepCount(scene, step);
  const double start = core::ThreadCpuSeconds();
  for (long i = 0; i < steps; ++i) engine->Step();
  return core::ThreadCpuSeconds() - start;
}

bool LoadScene(const core::AccuracyScene& scene, const std::string& worlds_dir,
               core::WorldDesc* world, std::string* why) {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  if (!core::LoadWorldFile(worlds_dir + "/" + scene.world, context, world)) {
    *why = diagnostics.FormatAll();
    return false;
  }
  if (scene.adjust) scene.adjust(world);
  return true;
}

}  // namespace

AccuracyRun RunPeerScene(const core::AccuracyScene& scene, const std::string& worlds_dir,
                         const core::AccuracySolver& solver, double step) {
  AccuracyRun run;
  run.scene = scene.name;
  run.solver = solver;
  run.step = step;
  try {
    core::WorldDesc world;
    PeerWorld peer;
    std::string why;
    if (!LoadScene(scene, worlds_dir, &world, &run.failure)) return run;
    world.settings.timestep = step;
    std::unique_ptr<PeerEngine> engine = MakePeerEngine(solver);
    if (!engine) throw std::invalid_argument(solver.Label() + " is not a peer");
    if (!BuildPeerWorld(world, &peer, &why) || !engine->Build(peer, step, &why)) {
      run.failure = "not expressed: " + why;
      return run;
    }
    // the engine must start where the world does, its surfaces touching at most (the worlds
    // place their bodies on their padding): a check of the conversions
    PeerReadout start;
    engine->Read(&start);
    const double mismatch = StartMismatch(world, start);
    if (!(mismatch < 1e-9) || !(start.deepest < 1e-6)) {
      char text[160];
      std::snprintf(
          text, sizeof text,
          "the engine starts %.3g from the world's state, its surfaces overlapping %.3g m",
          mismatch, start.deepest);
      run.failure = text;
      return run;
    }
    Measure(scene, world, engine.get(), step, &run);
    engine = MakePeerEngine(solver);
    engine->Build(peer, step, &why);
    run.cpu_seconds = TimeSteps(scene, engine.get(), step);
    run.real_time_factor = scene.duration / std::max(run.cpu_seconds, 1e-9);
  } catch (const std::exception& error) {
    run.failure = error.what();
  }
  return run;
}

}  // namespace lamina::peers
