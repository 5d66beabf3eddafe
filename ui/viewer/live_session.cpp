// SPDX-License-Identifier: MIT
#include "ui/viewer/live_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <utility>

#include "core/io/world_file.h"
#include "core/model/access_path.h"
#include "core/robot/kinematics.h"

namespace lamina::ui {

namespace {

using Clock = std::chrono::steady_clock;

// the physics publishes a frame at least this often while it cannot keep up (s of wall time),
// and batches at least this much simulated time between frames when it can
constexpr double kPublishInterval = 1.0 / 120.0;
// samples kept for TakeSamples when nobody takes them
constexpr size_t kMaxSamples = 100000;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// the --set arguments on a loaded description; false with an error naming the argument
bool ApplySets(const std::string& path, const std::vector<std::string>& sets,
               core::Diagnostics* diagnostics, core::WorldDesc* world) {
  for (const std::string& set : sets) {
    std::string target, value, error;
    if (!core::SplitAssignment(set, &target, &value, &error) ||
        !core::SetPathText(world, target, value, &error)) {
      diagnostics->Error({path, 0}, "--set '" + set + "': " + error);
      return false;
    }
  }
  return true;
}

std::string CanonicalPath(const std::string& requested) {
  std::error_code error;
  std::string path = std::filesystem::weakly_canonical(requested, error).string();
  return error || path.empty() ? requested : path;
}

RobotFrame RobotFrameOf(const core::Simulator& simulator, int robot) {
  RobotFrame frame;
  frame.sensed = simulator.GetRobotConfig(robot);
  if (!simulator.controller(robot).GetCommandedConfig(&frame.commanded)) {
    frame.commanded = frame.sensed;
  }
  frame.torques = simulator.GetActuatorTorques(robot);
  const core::RobotSensors& sensors = simulator.sensors(robot);
  frame.sensors = sensors.Readouts();
  frame.sensor_drawing =
      sensors.Drawing(core::LinkTransforms(simulator.world().robots[robot], frame.sensed));
  return frame;
}

// whether a body of `ids` is a robot's link (robot links are stopped only when their robot
// blew up: robot_guard.h, step_guard.h)
bool AnyRobotLink(const core::WorldDesc& world, const std::vector<int>& ids) {
  return std::any_of(ids.begin(), ids.end(), [&](int id) {
    return world.Resolve(id).kind == core::WorldId::Kind::kRobotLink;
  });
}

// what to try when the simulation stopped or had to be corrected
std::string ProblemText(const core::Simulator& simulator, core::StepStatus status,
                        const std::vector<int>& corrected) {
  char time[32];
  std::snprintf(time, sizeof(time), " at t = %.3f s", simulator.time());
  const std::string at = time;
  if (simulator.halted()) {
    return "The simulation stopped" + at + ": " + simulator.statistics().error +
           ". Undo the last edit, Reset, or lower kStiffness / raise padding or damping.";
  }
  if (status == core::StepStatus::kUnstable && AnyRobotLink(simulator.world(), corrected)) {
    // (its joints came apart, or its energy overflowed: robot_guard.h, step_guard.h)
    return "Energy blew up in " + core::BodiesText(simulator.world(), corrected) + at +
           " and the robot was stopped (paused). Try the exact or Newton solver, a smaller "
           "timestep, softer servo gains or a smaller command; Space resumes, Ctrl+Z undoes the "
           "last edit.";
  }
  if (status == core::StepStatus::kUnstable) {
    const std::string in =
        corrected.empty() ? "" : " in " + core::BodiesText(simulator.world(), corrected);
    return "Energy blew up" + in + at +
           " and was corrected (paused). Try lower kStiffness, more kDamping or padding, or a "
           "smaller timestep; Space resumes, Ctrl+Z undoes the last edit.";
  }
  if (status == core::StepStatus::kJointOpen) {
    char gap[32];
    std::snprintf(gap, sizeof(gap), "%.3g", simulator.statistics().max_joint_gap);
    const char* gains = simulator.robot_count() > 0 ? ", or softer servo gains" : "";
    return std::string("A joint came open (up to ") + gap + " m)" + at +
           ": the solver does not hold it at this step. Try the exact or Newton solver or a "
           "smaller timestep" +
           gains + ".";
  }
  return "";
}

}  // namespace

LiveSession::LiveSession(bool threaded) : threaded_(threaded) {
  frame_ = std::make_shared<SessionFrame>();
  auto_solver_ = threaded_;
  if (threaded_) thread_ = std::thread([this] { Loop(); });
}

LiveSession::~LiveSession() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

bool LiveSession::Load(const std::string& requested_path, const std::vector<std::string>& sets,
                       core::Diagnostics& diagnostics) {
  const std::string path = CanonicalPath(requested_path);
  const int errors_before = diagnostics.error_count();
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  core::WorldDesc world;
  std::unique_ptr<core::LiveWorld> live;
  try {
    if (!std::filesystem::is_regular_file(path)) {
      diagnostics.Error({path, 0}, "no such file");
    } else if (core::LoadWorldFile(path, context, &world) &&
               diagnostics.error_count() == errors_before &&
               ApplySets(path, sets, &diagnostics, &world)) {
      live = std::make_unique<core::LiveWorld>(core::WorldDocument(std::move(world), path));
      live->simulator().EnableContactFeedbackAll();
    }
  } catch (const std::exception& error) {
    diagnostics.Error({path, 0}, std::string("cannot build the simulation: ") + error.what());
    live.reset();
  }
  if (!live) return false;
  Install(std::move(live));
  return true;
}

void LiveSession::Install(std::unique_ptr<core::LiveWorld> world) {
  if (!threaded_) {
    Adopt(std::move(world));
    Publish();
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    incoming_ = std::move(world);
  }
  wake_.notify_all();
  Flush();
}

// the physics thread takes over a new world (lockstep: the caller)
void LiveSession::Adopt(std::unique_ptr<core::LiveWorld> world) {
  world_ = std::move(world);
  world_->simulator().SetErrorMeter(true);  // the Simulation panel shows it (LiveWorld keeps it)
  world_->AddStepObserver([this](const core::StepEvent& event) {
    smallest_step_ = smallest_step_ > 0.0 ? std::min(smallest_step_, event.h) : event.h;
    if (event.simulator.dragging()) drag_impulse_ += event.simulator.drag().force * event.h;
    for (int id : event.corrected_bodies) {
      if (std::find(corrected_.begin(), corrected_.end(), id) == corrected_.end())
        corrected_.push_back(id);
    }
  });
  owed_ = 0.0;
  worst_ = core::StepStatus::kNormal;
  clock_.Clear();
  meter_.Clear();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    choice_ = SolverChoice(physics_budget_);
  }
  chosen_.reset();
  world_solver_ = world_->document().desc().settings.solver_settings();
  user_chose_solver_ = false;
  problem_.clear();
}

// after commands: a reset or rebuild went back to the document's solver (the choice is put back),
// the user chose a solver in the settings (the choice ends for this world), or the choice was
// turned off (the world's solver is put back)
void LiveSession::KeepSolverChoice(bool auto_on) {
  if (!world_) return;
  core::Simulator& simulator = world_->simulator();
  const core::SolverSettings document = world_->document().desc().settings.solver_settings();
  // choosing a solver is the user's decision; tuning QuickStep's iterations is not
  if (document.type != world_solver_.type) user_chose_solver_ = true;
  world_solver_ = document;
  if (!auto_on) choice_.Clear();  // on again: measured anew
  if (chosen_) chosen_->quick_step_iterations = document.quick_step_iterations;
  if (chosen_ && (!auto_on || user_chose_solver_)) {
    chosen_.reset();
    if (simulator.solver() != document) simulator.SetSolver(document);
    return;
  }
  if (chosen_ && simulator.solver() != *chosen_) simulator.SetSolver(*chosen_);
}

// after steps: `step_wall` seconds of stepping gave `simulated` seconds
void LiveSession::MeasureSolver(double step_wall, double simulated, double speed, bool auto_on) {
  if (!auto_on || user_chose_solver_ || chosen_) return;
  core::Simulator& simulator = world_->simulator();
  const core::SolverSettings solver = simulator.solver();
  if (solver.type != core::SolverType::kStep) return;
  choice_.Add(step_wall, simulated, speed);
  if (!choice_.too_slow()) return;
  // the Newton solver: the exact solver's answer, faster (objects held by world joints and the
  // dragged body stay with dWorldStep inside it: object_islands.h)
  chosen_ = core::SolverSettings{core::SolverType::kNewton, solver.quick_step_iterations};
  simulator.SetSolver(*chosen_);
  const char* instead = "the Newton solver (the same answer)";
  char text[240];
  std::snprintf(text, sizeof text,
                "the exact solver reached %.2fx real time on this machine: playing with %s "
                "instead; the world keeps its solver",
                choice_.reachable_factor(), instead);
  std::lock_guard<std::mutex> lock(mutex_);
  messages_.push_back(text);
}

long LiveSession::Post(Command command) {
  long sequence = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    sequence = ++posted_;
    queue_.emplace_back(sequence, std::move(command));
  }
  wake_.notify_all();
  return sequence;
}

void LiveSession::SetPlaying(bool playing) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    playing_ = playing;
  }
  wake_.notify_all();
}

void LiveSession::SetSpeed(double speed) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (speed > 0.0 && std::isfinite(speed)) speed_ = speed;
}

std::string SolverText(const SessionFrame& frame) {
  if (frame.solver.type == core::SolverType::kStep) return "exact";
  char text[160];
  std::snprintf(text, sizeof text, "quick step (%d iterations)",
                frame.solver.quick_step_iterations);
  std::string out = frame.solver.type == core::SolverType::kNewton ? "newton" : text;
  if (frame.solver_chosen) {
    std::snprintf(text, sizeof text, ", chosen for real time: exact reached %.2fx",
                  frame.exact_factor);
    out += text;
  }
  return out;
}

void LiveSession::SetAutoSolver(bool on) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto_solver_ = on && threaded_;
  }
  wake_.notify_all();
}

void LiveSession::SetPhysicsBudget(double share_of_core) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (share_of_core >= 0.0 && std::isfinite(share_of_core)) physics_budget_ = share_of_core;
}

void LiveSession::SetSampledBody(int id) {
  std::lock_guard<std::mutex> lock(mutex_);
  sampled_body_ = id;
}

bool LiveSession::playing() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return playing_;
}

std::shared_ptr<const SessionFrame> LiveSession::frame() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return frame_;
}

std::vector<std::string> LiveSession::TakeMessages() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(messages_, {});
}

std::vector<SessionSample> LiveSession::TakeSamples() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<SessionSample> samples(samples_.begin(), samples_.end());
  samples_.clear();
  return samples;
}

void LiveSession::Flush() {
  if (!threaded_) {
    RunCommands();
    Publish();
    return;
  }
  std::unique_lock<std::mutex> lock(mutex_);
  const long wanted = posted_;
  done_.wait(lock,
             [&] { return stop_ || (incoming_ == nullptr && frame_->commands_done >= wanted); });
}

void LiveSession::RunCommands() {
  for (;;) {
    std::pair<long, Command> entry;
    std::unique_ptr<core::LiveWorld> incoming;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      incoming = std::move(incoming_);
      if (!incoming && queue_.empty()) return;
      if (!incoming) {
        entry = std::move(queue_.front());
        queue_.pop_front();
      }
    }
    if (incoming) {
      Adopt(std::move(incoming));
      continue;
    }
    std::string message = world_ ? entry.second(*world_) : "no world is open";
    problem_.clear();   // an edit, an undo, a reset: what went wrong may no longer hold
    shown_steps_ = -1;  // and the status is the next steps'
    std::lock_guard<std::mutex> lock(mutex_);
    done_count_ = entry.first;
    if (!message.empty()) messages_.push_back(std::move(message));
  }
}

void LiveSession::Advance(double wall_seconds) {
  RunCommands();
  double speed = 1.0;
  bool playing = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    speed = speed_;
    playing = playing_;
  }
  double simulated = 0.0;
  if (world_ && playing && !world_->simulator().halted()) {
    problem_.clear();
    core::Simulator& simulator = world_->simulator();
    const int steps = clock_.StepsForFrame(wall_seconds, speed, simulator.sim_step());
    const double before = simulator.time();
    for (int i = 0; i < steps && worst_ < core::StepStatus::kUnstable; ++i) {
      worst_ = std::max(worst_, simulator.Simulate(simulator.sim_step()));
    }
    simulated = simulator.time() - before;
  } else {
    clock_.Clear();
  }
  meter_.AddFrame(wall_seconds, simulated);
  Publish();
}

void LiveSession::StepNow(int steps) {
  RunCommands();
  if (world_) {
    core::Simulator& simulator = world_->simulator();
    for (int i = 0; i < steps; ++i) {
      worst_ = std::max(worst_, simulator.Simulate(simulator.sim_step()));
    }
  }
  Publish();
}

// the steps owed, one at a time, until they are done, `budget` seconds of wall time have passed,
// a command is waiting or the simulation needs the user
void LiveSession::RunSteps(double budget) {
  core::Simulator& simulator = world_->simulator();
  const auto start = Clock::now();
  const double h = simulator.sim_step();
  while (owed_ >= h * (1.0 - 1e-9) && worst_ < core::StepStatus::kUnstable) {
    worst_ = std::max(worst_, simulator.Simulate(h));
    owed_ -= h;
    if (SecondsSince(start) > budget) break;
    std::lock_guard<std::mutex> lock(mutex_);
    if (!queue_.empty() || incoming_ || stop_) break;
  }
}

void LiveSession::Loop() {
  auto last = Clock::now();
  for (;;) {
    RunCommands();
    const auto now = Clock::now();
    const double wall = std::chrono::duration<double>(now - last).count();
    last = now;
    double speed = 1.0;
    bool playing = false, auto_solver = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stop_) return;
      speed = speed_;
      playing = playing_;
      auto_solver = auto_solver_;
    }
    auto_solver_used_ = auto_solver;
    KeepSolverChoice(auto_solver);
    double simulated = 0.0;
    if (world_ && playing && !world_->simulator().halted()) {
      problem_.clear();
      const double before = world_->simulator().time();
      owed_ = std::min(owed_ + wall * speed, kMaxLag * speed);
      const auto start = Clock::now();
      RunSteps(kPublishInterval);
      simulated = world_->simulator().time() - before;
      MeasureSolver(SecondsSince(start), simulated, speed, auto_solver);
    } else {
      owed_ = 0.0;
    }
    meter_.AddFrame(wall, simulated);
    Publish();
    // sleep until a batch of steps is due, or a command, a world or the end arrives
    const double h = world_ ? world_->simulator().sim_step() : 0.0;
    const double due = playing ? std::max(h, kPublishInterval * speed) - owed_ : 0.05;
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait_for(lock, std::chrono::duration<double>(std::max(0.0, due / speed)), [&] {
      return stop_ || !queue_.empty() || incoming_ != nullptr || playing_ != playing;
    });
  }
}

void LiveSession::Publish() {
  int sampled = -1;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    sampled = sampled_body_;
  }
  auto frame = std::make_shared<SessionFrame>();
  if (world_) FillFrame(sampled, frame.get());
  frame->real_time_factor = meter_.factor();
  const bool stop_here = worst_ >= core::StepStatus::kUnstable;
  worst_ = frame->halted ? core::StepStatus::kError : core::StepStatus::kNormal;
  SessionSample sample;
  if (frame->loaded) FillSample(*frame, sampled, &sample);
  std::lock_guard<std::mutex> lock(mutex_);
  if (stop_here) {
    if (playing_) messages_.push_back(frame->problem);  // the status line says it once
    playing_ = false;                                   // the user decides what to do (ProblemText)
  }
  frame->playing = playing_;
  frame->speed = speed_;
  frame->auto_solver = auto_solver_used_;
  frame->commands_done = done_count_;
  if (frame->loaded) {
    samples_.push_back(std::move(sample));
    if (samples_.size() > kMaxSamples) samples_.pop_front();
  }
  frame_ = std::move(frame);
  done_.notify_all();
}

// the document's side of a frame (its description is copied only after an edit)
void LiveSession::FillDocument(SessionFrame* frame) {
  const core::WorldDocument& document = world_->document();
  if (!published_world_ || document.revision() != published_revision_) {
    published_world_ = std::make_shared<const core::WorldDesc>(document.desc());
    published_revision_ = document.revision();
  }
  if (document.saved_revision() != file_revision_ &&
      document.revision() == document.saved_revision()) {
    file_world_ = published_world_;
    file_revision_ = document.saved_revision();
  }
  frame->loaded = true;
  frame->world = published_world_;
  frame->file_world = file_world_;
  frame->path = document.path();
  frame->dirty = document.dirty();
  frame->undo_label = world_->history().UndoLabel();
  frame->redo_label = world_->history().RedoLabel();
}

// physics thread: everything but what the mutex guards
void LiveSession::FillFrame(int sampled, SessionFrame* frame) {
  FillDocument(frame);
  const core::Simulator& simulator = world_->simulator();
  frame->poses = core::CurrentPoses(simulator);
  frame->contacts = core::ContactMarkersFromSimulator(simulator);
  for (int r = 0; r < simulator.robot_count(); ++r) {
    frame->robots.push_back(RobotFrameOf(simulator, r));
  }
  frame->time = simulator.time();
  frame->step = simulator.sim_step();
  frame->solver = simulator.solver();
  frame->solver_chosen = chosen_.has_value();
  frame->exact_factor = choice_.reachable_factor();
  frame->smallest_step = std::exchange(smallest_step_, 0.0);
  frame->steps = simulator.statistics().steps;
  // (a reset or a new world counts from 0 again: a different count)
  if (simulator.statistics().steps != shown_steps_ || simulator.halted()) {
    shown_status_ = worst_;
    shown_steps_ = simulator.statistics().steps;
  }
  frame->status = shown_status_;
  frame->halted = simulator.halted();
  // an error shows while the simulation is halted; a corrected instability until it plays again
  std::string problem = ProblemText(simulator, worst_, corrected_);
  corrected_.clear();
  if (simulator.halted()) {
    frame->problem = std::move(problem);
  } else {
    if (!problem.empty()) problem_ = std::move(problem);
    frame->problem = problem_;
  }
  frame->kinetic_energy = simulator.KineticEnergy();
  frame->error_meter = simulator.error_meter_reading();
  frame->potential_energy = simulator.PotentialEnergy();
  frame->dragging = simulator.dragging();
  frame->drag = simulator.drag();
  frame->drag_impulse = std::exchange(drag_impulse_, core::Vec3::Zero());
  for (int id = 0; id < simulator.body_count(); ++id) {
    if (simulator.HasKinematicTarget(id)) frame->kinematic.push_back(id);
  }
  frame->sampled_velocity = SampledVelocity(sampled);
  frame->sampled_contacts = core::ReadContacts(simulator, sampled);
}

core::Twist LiveSession::SampledVelocity(int sampled) const {
  const std::optional<core::ElementIndex> element =
      core::ElementOfWorldId(world_->document().desc(), sampled);
  if (!element || element->kind != core::ElementKind::kObject) return {};
  return world_->simulator().GetObjectVelocity(element->index);
}

void LiveSession::FillSample(const SessionFrame& frame, int sampled, SessionSample* sample) const {
  sample->time = frame.time;
  sample->kinetic = frame.kinetic_energy;
  sample->potential = frame.potential_energy;
  sample->step = frame.smallest_step > 0.0 ? frame.smallest_step : frame.step;
  sample->real_time_factor = frame.real_time_factor;
  sample->body = sampled;
  for (const RobotFrame& robot : frame.robots) {
    sample->sensors.emplace_back();
    for (const core::SensorReadout& sensor : robot.sensors) {
      sample->sensors.back().push_back(sensor.values);
    }
  }
  if (sampled < 0 || !world_) return;
  sample->contact_force = world_->simulator().ContactForce(sampled).norm();
  for (const core::PairReadout& pair : frame.sampled_contacts) {
    sample->overlap = std::max(sample->overlap, pair.max_depth);
  }
  const core::WorldDesc& world = *frame.world;
  const std::optional<core::ElementIndex> element = core::ElementOfWorldId(world, sampled);
  if (!element || element->kind != core::ElementKind::kLink) return;
  sample->robot = element->index;
  const RobotFrame& robot = frame.robots[element->index];
  sample->sensed = robot.sensed;
  sample->commanded = robot.commanded;
  sample->torques = robot.torques;
}

}  // namespace lamina::ui
