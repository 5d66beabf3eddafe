// SPDX-License-Identifier: MIT
#include "core/edit/live_world.h"

#include <exception>

namespace lamina::core {

/// The history's view of a LiveWorld.
class LiveWorld::Target final : public EditTarget {
 public:
  explicit Target(LiveWorld* live) : live_(live) {}
  WorldDocument& document() override { return live_->document_; }
  bool Apply(const Edit& edit, std::string* error) override { return live_->Apply(edit, error); }
  void BeginStep(HistoryEntry& entry, HistoryStep step) override { live_->BeginStep(entry, step); }
  void EndStep(HistoryEntry& entry, HistoryStep step) override { live_->EndStep(entry, step); }

 private:
  LiveWorld* live_;
};

LiveWorld::LiveWorld(WorldDocument document)
    : document_(std::move(document)),
      simulator_(std::make_unique<Simulator>(document_.desc())),
      target_(std::make_unique<Target>(this)) {
  AttachObservers(simulator_.get());
}

LiveWorld::~LiveWorld() = default;

bool LiveWorld::Load(const std::string& path, Diagnostics& diagnostics) {
  WorldDocument loaded;
  if (!loaded.Load(path, diagnostics)) return false;
  auto simulator = std::make_unique<Simulator>(loaded.desc());
  simulator->SetErrorMeter(simulator_->error_meter());
  document_ = std::move(loaded);
  AttachObservers(simulator.get());
  simulator_ = std::move(simulator);
  history_.Clear();
  return true;
}

int LiveWorld::AddStepObserver(StepObserver observer) {
  observers_.emplace_back(next_observer_, std::move(observer));
  return next_observer_++;
}

void LiveWorld::RemoveStepObserver(int id) {
  std::erase_if(observers_, [id](const auto& entry) { return entry.first == id; });
}

// one observer on each simulation that calls this world's observers, so that they outlive the
// simulations structural edits replace
void LiveWorld::AttachObservers(Simulator* simulator) {
  simulator->AddStepObserver([this](const StepEvent& event) {
    for (size_t i = 0; i < observers_.size(); ++i) observers_[i].second(event);
  });
}

bool LiveWorld::Do(const Edit& edit, std::string* error) {
  return history_.Do(*target_, edit, error);
}

bool LiveWorld::Undo(std::string* error) {
  return history_.Undo(*target_, error);
}

bool LiveWorld::Redo(std::string* error) {
  return history_.Redo(*target_, error);
}

// ---- applying one edit to the document and the simulation --------------------------------

bool LiveWorld::Apply(const Edit& edit, std::string* error) {
  if (const auto* param = std::get_if<ParamEdit>(&edit)) return ApplyParam(*param, error);
  if (const auto* state = std::get_if<InitialStateEdit>(&edit)) {
    return ApplyInitialState(*state, error);
  }
  return ApplyStructural(edit, error);
}

// the document as it was before `edit` (applied to it) and its revision then
void LiveWorld::TakeBack(const Edit& edit, Revision revision) {
  std::string ignored;
  core::Apply(Inverse(edit), &document_, &ignored);
  DocumentAccess::SetRevision(&document_, revision);
}

bool LiveWorld::ApplyParam(const ParamEdit& edit, std::string* error) {
  const Revision revision = document_.revision();
  if (!edit.Apply(&document_, error)) return false;
  const ElementIndex element = *document_.Resolve(edit.element);
  const ParamSpec& spec = Params()[edit.param];
  if (!simulator_->SetParam(element, spec, edit.after, error)) {
    TakeBack(edit, revision);
    return false;
  }
  if (spec.apply == ParamApply::kOnReset && AtStart()) simulator_->Reset();
  return true;
}

// nothing simulated since the start: the running state is the initial one
bool LiveWorld::AtStart() const {
  return simulator_->time() == 0.0 && simulator_->statistics().steps == 0 && !simulator_->halted();
}

bool LiveWorld::ApplyInitialState(const InitialStateEdit& edit, std::string* error) {
  const Revision revision = document_.revision();
  if (!edit.Apply(&document_, error)) return false;
  if (SetInitialState(edit.after, error)) return true;
  std::string ignored;
  SetInitialState(edit.before, &ignored);
  TakeBack(edit, revision);
  return false;
}

// the initial-condition rows of the simulated description (what Reset starts from)
bool LiveWorld::SetInitialState(const InitialState& state, std::string* error) {
  const auto set = [&](const ElementIndex& element, std::string_view key, ParamValue value) {
    return simulator_->SetParam(element, *FindParam(key, element.kind), value, error);
  };
  const auto vector = [](const VecX& v) { return ParamValue(v.data(), v.data() + v.size()); };
  for (const ObjectInitialState& object : state.objects) {
    const ElementIndex element = ElementIndex::Object(document_.ObjectIndex(object.uid));
    if (!set(element, "transform", PoseToValue(object.pose)) ||
        !set(element, "velocity", TwistToValue(object.velocity))) {
      return false;
    }
  }
  for (const RobotInitialState& robot : state.robots) {
    const ElementIndex element = ElementIndex::Robot(document_.RobotIndex(robot.uid));
    if (!set(element, "config", vector(robot.config)) ||
        !set(element, "velocity", vector(robot.velocity))) {
      return false;
    }
  }
  return true;
}

bool LiveWorld::ApplyStructural(const Edit& edit, std::string* error) {
  const Revision revision = document_.revision();
  const WorldLayout old_layout = LayoutOf(document_.desc());
  if (!core::Apply(edit, &document_, error)) return false;
  try {
    RebuildSimulator(old_layout);
  } catch (const std::exception& e) {
    TakeBack(edit, revision);
    if (error) *error = std::string("the simulation could not be built: ") + e.what();
    return false;
  }
  return true;
}

// a new simulation of the document that takes over the old one's state (see the header); the
// old one stays until the new one is complete
void LiveWorld::RebuildSimulator(const WorldLayout& old_layout) {
  auto fresh = std::make_unique<Simulator>(document_.desc());
  Simulator& old = *simulator_;
  const WorldLayout layout = LayoutOf(document_.desc());
  const std::vector<int> id_map = MapWorldIds(old_layout, layout);
  fresh->SetSolver(old.solver());
  fresh->SetSleeping(old.sleeping());
  fresh->SetErrorMeter(old.error_meter());
  CarryBodyFlags(&old, id_map, fresh.get());
  for (const auto& [a, b] : CarryPairs(id_map, old.ContactFeedbackPairs())) {
    fresh->EnableContactFeedback(a, b);
  }
  if (!old.halted()) {
    std::vector<bool> moves(fresh->body_count());
    for (int id = 0; id < fresh->body_count(); ++id) moves[id] = fresh->BodyMoves(id);
    fresh->SetState(CarryState(old_layout, old.GetState(), layout, moves, fresh->GetState()));
  }
  AttachObservers(fresh.get());
  simulator_ = std::move(fresh);
}

// which bodies were disabled or kinematic (SimBody::Enable, EnableDynamics)
void LiveWorld::CarryBodyFlags(Simulator* old, const std::vector<int>& id_map, Simulator* fresh) {
  for (int id = 0; id < old->body_count() && id < static_cast<int>(id_map.size()); ++id) {
    if (id_map[id] < 0) continue;
    SimBody was = old->body(id);
    SimBody now = fresh->body(id_map[id]);
    if (!was.valid() || !now.valid()) continue;  // a robot's own id is not a body
    if (!was.enabled()) now.Enable(false);
    // a kinematic target ends with the old simulation: its body is dynamic again
    if (old->HasKinematicTarget(id)) continue;
    if (now.dynamics_enabled() && !was.dynamics_enabled()) now.EnableDynamics(false);
  }
}

// ---- the states each history entry keeps -------------------------------------------------

LiveWorld::Mark LiveWorld::MarkNow() const {
  return {simulator_->GetState(), simulator_->statistics().steps, !simulator_->halted()};
}

bool LiveWorld::AtMark(const Mark& mark) const {
  return mark.usable && !simulator_->halted() && simulator_->statistics().steps == mark.steps &&
         simulator_->GetState() == mark.state;
}

void LiveWorld::BeginStep(HistoryEntry& entry, HistoryStep step) {
  pending_ = MarkNow();
  if (step == HistoryStep::kDo) {
    entry.record = StateRecord{pending_, {}};
    return;
  }
  const StateRecord& record = std::any_cast<const StateRecord&>(entry.record);
  const Mark& leaving = step == HistoryStep::kUndo ? record.applied : record.unapplied;
  pending_exact_ = !pending_.usable || AtMark(leaving);
}

void LiveWorld::EndStep(HistoryEntry& entry, HistoryStep step) {
  StateRecord& record = std::any_cast<StateRecord&>(entry.record);
  if (step == HistoryStep::kDo) {
    // an entry that grew (a slider drag) while the simulation ran cannot be undone by restoring
    // the state from before its first edit: that would throw the simulated time away
    if (record.applied.usable && !AtMark(record.applied)) record.unapplied.usable = false;
    record.applied = MarkNow();
    return;
  }
  Mark& leaving = step == HistoryStep::kUndo ? record.applied : record.unapplied;
  Mark& landing = step == HistoryStep::kUndo ? record.unapplied : record.applied;
  if (pending_exact_ && landing.usable) simulator_->SetState(landing.state);
  // the side left behind is where the simulation was (unless that was a broken state)
  if (pending_.usable) leaving = std::move(pending_);
  landing = MarkNow();
}

// ---- the current state as the initial state -----------------------------------------------

InitialState LiveWorld::CurrentState() const {
  InitialState state;
  const WorldDesc& world = document_.desc();
  for (int i = 0; i < simulator_->object_count(); ++i) {
    state.objects.push_back(
        {world.objects[i].uid, simulator_->GetObjectPose(i), simulator_->GetObjectVelocity(i)});
  }
  for (int r = 0; r < simulator_->robot_count(); ++r) {
    state.robots.push_back(
        {world.robots[r].uid, simulator_->GetRobotConfig(r), simulator_->GetRobotVelocity(r)});
  }
  return state;
}

bool LiveWorld::MakeCurrentStateInitial(std::string* error) {
  return Do(MakeInitialStateEdit(document_, CurrentState()), error);
}

}  // namespace lamina::core
