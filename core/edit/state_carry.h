// SPDX-License-Identifier: MIT
// Carrying a running simulation's state across a structural edit (rename, add, remove or
// reorder): the simulation is built anew from the edited description and takes over, element by
// element (matched by uid), the state of the old one. This is MuJoCo's mj_recompile ("preserving
// the state"), made explicit: world ids shift when an object is added or removed, so every
// id-keyed piece of state (friction anchors, contact-feedback pairs, body flags) is renumbered.
// Klamp't has no such path: its world ids are positions and an edit means a new simulation.
// Pure functions of descriptions and states; LiveWorld applies them.
#pragma once

#include <utility>
#include <vector>

#include "core/model/world_desc.h"
#include "core/sim/sim_state.h"

namespace lamina::core {

/// What world ids are made of: the uids of the terrains, objects and robots in order, and each
/// robot's link count (Klamp't numbering: terrains, objects, then each robot and its links).
struct WorldLayout {
  std::vector<ElementUid> terrains, objects, robots;
  std::vector<int> robot_links;  ///< per robot
};
WorldLayout LayoutOf(const WorldDesc& world);

/// For every world id of `from`, the id of the same body in `to` (by uid; a link by its
/// index), or -1 when it is not there.
std::vector<int> MapWorldIds(const WorldLayout& from, const WorldLayout& to);

/// The state of a simulation of `to` that continues `state` (of `from`): time; each object's
/// body state and sleep, and each robot's bodies, joints and controller, moved to their new
/// positions by uid; friction anchors renumbered (those of bodies that are gone dropped; a pair
/// whose bodies swapped order is re-expressed from the other side, as the simulator orients
/// pairs: the lower id moves when it has an ODE body, `moves[id]` of `to`, else the higher one).
/// Elements new in `to` keep their state from `to_initial` (the new simulation's own start:
/// initial pose and velocity, awake).
SimState CarryState(const WorldLayout& from, const SimState& state, const WorldLayout& to,
                    const std::vector<bool>& moves, SimState to_initial);

/// Contact-feedback pairs (world ids of `from`) renumbered for `to`; pairs of a body that is
/// gone are dropped.
std::vector<std::pair<int, int>> CarryPairs(const std::vector<int>& id_map,
                                            const std::vector<std::pair<int, int>>& pairs);

}  // namespace lamina::core
