// SPDX-License-Identifier: MIT
// LiveWorld: a world document, the simulation running it, and the history of its edits — the
// one object the viewer and the batch tools hold. Every edit reaches the document and the
// simulation together, or neither.
//
// How an edit reaches the simulation:
//  * ParamEdit: Simulator::SetParam on the element the reference resolves to (live rows from the
//    next step; padding rebuilds the body's geometry; mass, inertia, centre of mass and preshrink
//    rebuild the simulation in its state; initial conditions change only what Reset starts from).
//    An initial condition edited while the simulation has not left its start (time 0, no step
//    taken: a world just loaded or reset) also moves the running state there (Reset), so that
//    posing a paused world's bodies moves what is shown; later, only what Reset starts from.
//  * InitialStateEdit: the initial-condition rows of every element it lists (what Reset starts
//    from); the running state is untouched.
//  * Rename, add, remove, move: a new Simulator is built from the document and takes over the
//    running state by uid (CarryState: time, bodies, robots with their controllers, friction
//    anchors, sleep), plus the solver and sleeping settings of the old one, its contact-feedback
//    pairs and which bodies were disabled or kinematic, renumbered, and this world's step
//    observers. A new object starts at its initial pose; statistics start from zero; a drag, a
//    kinematic target (its body is dynamic again) and held wrenches end. A simulation stopped by an
//    error is not carried: the new one starts at the initial state. This is MuJoCo's mj_recompile,
//    made explicit. References to simulator() do not survive a structural edit (a new object).
//
// Exact undo. Every history entry keeps the simulation state (SimState and step count) on each
// side of it: just before it was applied and just after. Undoing an entry while the simulation
// is still exactly where the entry left it (same step count, same SimState: nothing simulated,
// nothing moved since) applies the inverse edits and then restores the state from before the
// entry, so Do + Undo is a no-op bit for bit and the simulation continues exactly as if the edit
// had never been made. Otherwise the inverse edits are applied live and the simulation goes on
// from where it is. Redo likewise: right after an undo it restores the state the entry had
// left. When the simulation was stopped by an error (Simulator::halted), undo always restores
// the state from before the entry (SetState rebuilds a stopped simulation): undoing the edit
// that broke the simulation revives it there. Not restored: statistics, applied forces,
// contact-feedback readings of the last call, and edits made on simulator() directly (which
// are not in the document).
//
// Saving saves the document: gains and friction edited live through ParamEdit are in it (the
// simulator's controllers read the drivers of its own description, RobotController::ViewOf).
// Klamp't's SimTest edits the simulator and saves robot files from it; here the simulator is
// never the source of what is saved.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/diagnostics.h"
#include "core/edit/document.h"
#include "core/edit/edit.h"
#include "core/edit/history.h"
#include "core/edit/state_carry.h"
#include "core/sim/simulator.h"

namespace lamina::core {

class LiveWorld {
 public:
  /// Runs `document` from its initial state.
  explicit LiveWorld(WorldDocument document);
  ~LiveWorld();
  LiveWorld(const LiveWorld&) = delete;
  LiveWorld& operator=(const LiveWorld&) = delete;

  /// Loads a world file as the document (WorldDocument::Load) and runs it, the history emptied;
  /// on failure everything stays as it was.
  bool Load(const std::string& path, Diagnostics& diagnostics);
  bool Save(Diagnostics& diagnostics) { return document_.Save(diagnostics); }
  bool SaveAs(const std::string& path, Diagnostics& diagnostics) {
    return document_.SaveAs(path, diagnostics);
  }

  const WorldDocument& document() const { return document_; }
  /// The running simulation (step it, read it, interact with it). A structural edit replaces it.
  Simulator& simulator() { return *simulator_; }
  const Simulator& simulator() const { return *simulator_; }
  const History& history() const { return history_; }

  /// Applies `edit` to the document and the simulation and records it; false with `error`
  /// (both unchanged) when it is refused.
  bool Do(const Edit& edit, std::string* error = nullptr);
  bool Undo(std::string* error = nullptr);
  bool Redo(std::string* error = nullptr);
  bool CanUndo() const { return history_.CanUndo(); }
  bool CanRedo() const { return history_.CanRedo(); }
  void BeginGroup(std::string label) { history_.BeginGroup(std::move(label)); }
  void EndGroup() { history_.EndGroup(); }

  /// `observer` is called after every accepted step of the running simulation, whichever it is:
  /// it stays across the new simulations that structural edits and Load build (observers added
  /// on simulator() directly do not). Not to be added or removed from inside an observer.
  int AddStepObserver(StepObserver observer);
  void RemoveStepObserver(int id);

  /// The simulation's current object poses and velocities and robot configurations and
  /// velocities, keyed by uid.
  InitialState CurrentState() const;
  /// Do(InitialStateEdit): the current state becomes what Reset starts from. Refused (false,
  /// `error`) when the state is not finite (a simulation stopped by an error).
  bool MakeCurrentStateInitial(std::string* error = nullptr);

 private:
  class Target;
  friend class Target;

  struct Mark {
    SimState state;
    long steps = 0;
    bool usable = false;  ///< taken from a running simulation (not one stopped by an error)
  };
  /// What an entry keeps (HistoryEntry::record).
  struct StateRecord {
    Mark unapplied, applied;
  };

  bool Apply(const Edit& edit, std::string* error);
  bool ApplyParam(const ParamEdit& edit, std::string* error);
  bool ApplyInitialState(const InitialStateEdit& edit, std::string* error);
  bool SetInitialState(const InitialState& state, std::string* error);
  bool ApplyStructural(const Edit& edit, std::string* error);
  void RebuildSimulator(const WorldLayout& old_layout);
  void CarryBodyFlags(Simulator* old, const std::vector<int>& id_map, Simulator* fresh);
  void AttachObservers(Simulator* simulator);
  void TakeBack(const Edit& edit, Revision revision);
  void BeginStep(HistoryEntry& entry, HistoryStep step);
  void EndStep(HistoryEntry& entry, HistoryStep step);
  Mark MarkNow() const;
  bool AtStart() const;
  bool AtMark(const Mark& mark) const;

  WorldDocument document_;
  std::unique_ptr<Simulator> simulator_;
  History history_;
  std::unique_ptr<Target> target_;
  std::vector<std::pair<int, StepObserver>> observers_;
  int next_observer_ = 0;
  Mark pending_;                ///< the state when the current step began
  bool pending_exact_ = false;  ///< the current undo/redo restores the recorded state
};

}  // namespace lamina::core
