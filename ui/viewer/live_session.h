// SPDX-License-Identifier: MIT
// LiveSession: the editor's world — a core::LiveWorld (document, simulation, undo history)
// stepped in real time on its own thread, and the frames the window draws.
//
// Threads. The physics thread owns the LiveWorld; nothing else touches it. The window's thread
// (the main thread: GL, ImGui) talks to it in two ways only:
//  * Post(command): edits, mouse-tool input, reset, save, load... go through one queue and are
//    carried out in order between two physics steps (never during one), so an edit applies at
//    the next step exactly as in a scripted run;
//  * frame(): the latest finished state (poses, contacts, the document's description, robot
//    values, drag readout, real-time factor), an immutable SessionFrame shared by pointer. The
//    window draws whatever frame is latest and never waits for the physics.
// MuJoCo's simulate runs physics on its own thread too but shares mjModel/mjData under one mutex
// that the render thread holds while it copies the scene; here the physics publishes and the
// renderer takes, so a slow step never stalls a frame and a slow frame never stalls physics.
//
// Pacing. Simulated time follows the wall clock times the speed; a world too heavy to keep up
// runs slower than real time (debt beyond kMaxLag is dropped, not caught up in a burst), and the
// real-time factor shown is what was achieved. Lockstep mode (threaded = false) runs everything
// on the caller's thread inside Advance(wall seconds): scripted tests and recordings get the same
// steps whatever the machine's speed.
//
// Samples. Every published frame also appends one SessionSample (time, energies, step, real-time
// factor, the selected body's contact force and overlap, its robot's joints), and TakeSamples
// hands the ones not taken yet to the plots, so a frame the window skips loses no sample.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/diagnostics.h"
#include "core/edit/live_world.h"
#include "core/render/contact_markers.h"
#include "core/render/world_poses.h"
#include "core/sensors/robot_sensors.h"
#include "core/sim/contact_readout.h"
#include "ui/viewer/sim_clock.h"
#include "ui/viewer/solver_choice.h"

namespace lamina::ui {

/// A robot's joints in one frame, link space (rad or m): sensed, commanded (the controller's
/// PID targets, or the sensed value where a driver is not in PID mode) and the driver efforts.
struct RobotFrame {
  core::VecX sensed, commanded;
  core::VecX torques;                        ///< per driver, clamped efforts (N·m or N)
  std::vector<core::SensorReadout> sensors;  ///< every sensor's name, type and measurements
  core::SensorDrawing sensor_drawing;        ///< the sensors in 3-D (the `sensors` overlay)
};

/// What one published frame shows. Immutable once published.
struct SessionFrame {
  bool loaded = false;
  /// The document's description (shared by every frame until the next edit).
  std::shared_ptr<const core::WorldDesc> world;
  /// The document as last loaded or saved (what "back to the file's value" goes back to).
  std::shared_ptr<const core::WorldDesc> file_world;
  std::string path;  ///< where Save writes ("" before Save As)
  bool dirty = false;
  std::string undo_label, redo_label;  ///< "" when there is nothing to undo / redo

  core::WorldPoses poses;
  std::vector<core::ContactMarker> contacts;
  std::vector<RobotFrame> robots;
  double time = 0.0;  ///< simulated, s
  double step = 0.0;  ///< the world's timestep, s
  /// the shortest accepted sub-step since the previous frame (adaptive stepping halves it), s
  double smallest_step = 0.0;
  long steps = 0;
  /// the worst of the steps taken since the previous frame; when none was taken (paused), the
  /// status of the last steps taken, so that a pause after an instability still says it
  core::StepStatus status = core::StepStatus::kNormal;
  bool halted = false;  ///< an error stopped the simulation (undo, reset or an edit revives it)
  std::string problem;  ///< what went wrong and what to try; "" when all is well
  bool playing = false;
  double speed = 1.0;
  double real_time_factor = 0.0;
  double kinetic_energy = 0.0, potential_energy = 0.0;  ///< J
  /// The live accuracy meter (core/sim/error_meter.h): position error growth, m per simulated s.
  core::ErrorMeterReading error_meter;
  bool dragging = false;
  core::DragState drag;
  /// ∫ drag force dt over the steps since the previous frame (N·s, world): what the mouse spring
  /// gave the grabbed body, every step counted (drag.force is the last step's force only).
  core::Vec3 drag_impulse = core::Vec3::Zero();
  std::vector<int> kinematic;  ///< world ids of bodies moved by a kinematic target
  /// The sampled body (SetSampledBody) when it is an object: its velocity now (frame origin).
  core::Twist sampled_velocity;
  /// The sampled body's contacts now: partners, blended surfaces and their rules, overlaps,
  /// normal forces (core::ReadContacts).
  std::vector<core::PairReadout> sampled_contacts;

  /// The solver the simulation runs now, and whether the real-time choice (solver_choice.h)
  /// put the Newton solver in place of the world's exact solver; exact_factor is the real-time
  /// factor the exact solver reached when it was measured (0: not measured).
  core::SolverSettings solver;
  bool solver_chosen = false;
  bool auto_solver = false;  ///< the real-time choice is on
  double exact_factor = 0.0;

  long commands_done = 0;  ///< sequence number of the last command carried out
};

/// The solver a frame's simulation runs: "exact", "quick step (20 iterations)", or "quick step
/// (20 iterations), chosen for real time: exact reached 0.52x".
std::string SolverText(const SessionFrame& frame);

/// One row of the plots (see the file comment).
struct SessionSample {
  double time = 0.0;
  double kinetic = 0.0, potential = 0.0;
  double step = 0.0, real_time_factor = 0.0;
  int body = -1;                              ///< the selected body (-1: none)
  double contact_force = 0.0, overlap = 0.0;  ///< its total contact force (N), deepest overlap (m)
  int robot = -1;                             ///< the selected body's robot (-1: none)
  core::VecX sensed, commanded, torques;      ///< that robot's, as in RobotFrame
  /// Every robot's sensor measurements (per robot, per sensor; cameras empty).
  std::vector<std::vector<std::vector<double>>> sensors;
};

class LiveSession {
 public:
  /// A command carried out on the physics thread between two steps. It may return a message for
  /// the status line ("" for none): a refused edit says why.
  using Command = std::function<std::string(core::LiveWorld& world)>;

  /// Largest simulated-time debt carried when the physics cannot keep up, s.
  static constexpr double kMaxLag = 0.1;

  /// `threaded`: physics on its own thread, paced by the wall clock; otherwise lockstep (Advance).
  explicit LiveSession(bool threaded);
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  /// Loads a world file (with --set PATH=VALUE assignments applied first) on the caller's thread
  /// and, on success, hands it to the physics: history emptied, time 0. On failure the current
  /// world stays and `diagnostics` says why. Safe to call while running.
  bool Load(const std::string& path, const std::vector<std::string>& sets,
            core::Diagnostics& diagnostics);

  /// Queues `command`; the sequence number it will have in SessionFrame::commands_done.
  long Post(Command command);
  void SetPlaying(bool playing);
  void SetSpeed(double speed);
  /// The body whose contacts and robot the samples follow (-1: none).
  void SetSampledBody(int id);
  /// The real-time solver choice (solver_choice.h): on by default with a physics thread, never
  /// in lockstep. Off puts the world's own solver back. Choosing a solver in the settings also
  /// ends it for that world (the user's decision wins).
  void SetAutoSolver(bool on);
  /// The share of one core the physics may take before the choice switches to the Newton solver
  /// (SolverChoice::kPhysicsBudget unless set; 0: any measured cost is too much). Takes effect
  /// for the next world loaded.
  void SetPhysicsBudget(double share_of_core);

  /// Lockstep only: carries out the queued commands, then simulates the steps owed for
  /// `wall_seconds` at the current speed, then publishes a frame.
  void Advance(double wall_seconds);
  /// Lockstep only: the queued commands, then `steps` physics steps (while paused: "step").
  void StepNow(int steps);
  /// Blocks until every command posted so far has been carried out and published.
  void Flush();

  std::shared_ptr<const SessionFrame> frame() const;
  /// The messages of commands carried out since the last call, oldest first.
  std::vector<std::string> TakeMessages();
  /// The plot samples published since the last call, oldest first.
  std::vector<SessionSample> TakeSamples();
  bool threaded() const { return threaded_; }
  /// Whether the physics is playing now (it pauses itself on an error or instability).
  bool playing() const;

 private:
  void Loop();
  void RunCommands();
  void RunSteps(double budget_seconds);
  void Publish();
  void FillDocument(SessionFrame* frame);
  void FillFrame(int sampled, SessionFrame* frame);
  void FillSample(const SessionFrame& frame, int sampled, SessionSample* sample) const;
  core::Twist SampledVelocity(int sampled) const;
  void Install(std::unique_ptr<core::LiveWorld> world);
  void KeepSolverChoice(bool auto_on);
  void MeasureSolver(double step_wall, double simulated, double speed, bool auto_on);
  void Adopt(std::unique_ptr<core::LiveWorld> world);

  const bool threaded_;
  std::unique_ptr<core::LiveWorld> world_;  ///< the physics thread's (lockstep: the caller's)
  std::shared_ptr<const core::WorldDesc> published_world_;
  core::Revision published_revision_ = 0;
  std::shared_ptr<const core::WorldDesc> file_world_;
  core::Revision file_revision_ = 0;

  mutable std::mutex mutex_;  ///< guards everything below
  std::condition_variable wake_, done_;
  std::deque<std::pair<long, Command>> queue_;
  long posted_ = 0, done_count_ = 0;
  std::shared_ptr<const SessionFrame> frame_;
  std::vector<std::string> messages_;
  std::deque<SessionSample> samples_;
  std::unique_ptr<core::LiveWorld> incoming_;  ///< a loaded world waiting for the physics
  bool playing_ = true;
  double speed_ = 1.0;
  int sampled_body_ = -1;
  bool auto_solver_ = false;
  double physics_budget_ = SolverChoice::kPhysicsBudget;
  bool stop_ = false;

  // physics thread only
  double owed_ = 0.0;
  core::StepStatus worst_ = core::StepStatus::kNormal;
  core::StepStatus shown_status_ = core::StepStatus::kNormal;  ///< of the last frame that stepped
  long shown_steps_ = -1;                         ///< the simulator's step count at that frame
  double smallest_step_ = 0.0;                    ///< since the previous frame (0: no step)
  core::Vec3 drag_impulse_ = core::Vec3::Zero();  ///< since the previous frame
  std::vector<int> corrected_;  ///< bodies the stability checks corrected since the previous frame
  std::string problem_;  ///< what went wrong, until play resumes, a command runs or a world opens
  RealTimeFactorMeter meter_;
  SolverChoice choice_;
  std::optional<core::SolverSettings> chosen_;  ///< the Newton solver, chosen for real time
  core::SolverSettings world_solver_;           ///< the document's when the world was adopted
  bool user_chose_solver_ = false;              ///< the solver row was edited: no choice made
  bool auto_solver_used_ = false;               ///< auto_solver_ as the loop last acted on it
  FixedStepClock clock_;                        ///< lockstep pacing
  std::thread thread_;
};

}  // namespace lamina::ui
