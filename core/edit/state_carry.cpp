// SPDX-License-Identifier: MIT
#include "core/edit/state_carry.h"

#include <algorithm>
#include <compare>
#include <map>

#include "core/sim/friction_anchor.h"

namespace lamina::core {

namespace {

// a body of a world independent of its position: kind, uid, link
struct BodyKey {
  int kind = 0;  // 0 terrain, 1 object, 2 robot, 3 link
  ElementUid uid = 0;
  int link = -1;
  auto operator<=>(const BodyKey&) const = default;
};

// the key of every world id, in id order
std::vector<BodyKey> KeysOf(const WorldLayout& layout) {
  std::vector<BodyKey> keys;
  for (ElementUid uid : layout.terrains) keys.push_back({0, uid, -1});
  for (ElementUid uid : layout.objects) keys.push_back({1, uid, -1});
  for (size_t r = 0; r < layout.robots.size(); ++r) {
    keys.push_back({2, layout.robots[r], -1});
    for (int l = 0; l < layout.robot_links[r]; ++l) keys.push_back({3, layout.robots[r], l});
  }
  return keys;
}

int IndexOf(const std::vector<ElementUid>& uids, ElementUid uid) {
  const auto found = std::find(uids.begin(), uids.end(), uid);
  return found == uids.end() ? -1 : static_cast<int>(found - uids.begin());
}

// a's anchor in b's frame as b's in a's frame
FrictionAnchor Reversed(const FrictionAnchor& anchor) {
  FrictionAnchor reversed;
  reversed.a = anchor.b;
  reversed.b = anchor.a;
  reversed.rotation = anchor.rotation.transpose();
  reversed.position = -(anchor.rotation.transpose() * anchor.position);
  return reversed;
}

int MapId(const std::vector<int>& id_map, int id) {
  return id >= 0 && id < static_cast<int>(id_map.size()) ? id_map[id] : -1;
}

// the simulator orients a pair as FindPairContacts does: a is the lower id when that body moves
// (has an ODE body), else the higher one
std::vector<FrictionAnchor> CarryAnchors(const std::vector<int>& id_map,
                                         const std::vector<bool>& moves,
                                         const std::vector<FrictionAnchor>& anchors) {
  std::vector<FrictionAnchor> carried;
  for (FrictionAnchor anchor : anchors) {
    anchor.a = MapId(id_map, anchor.a);
    anchor.b = MapId(id_map, anchor.b);
    if (anchor.a < 0 || anchor.b < 0) continue;
    const int lower = std::min(anchor.a, anchor.b), upper = std::max(anchor.a, anchor.b);
    const bool lower_moves = lower < static_cast<int>(moves.size()) && moves[lower];
    const int moving = lower_moves ? lower : upper;
    carried.push_back(anchor.a == moving ? anchor : Reversed(anchor));
  }
  SortAnchors(&carried);
  return carried;
}

template <typename T>
void CarryByUid(const std::vector<ElementUid>& from, const std::vector<T>& values,
                const std::vector<ElementUid>& to, std::vector<T>* out) {
  for (size_t i = 0; i < to.size() && i < out->size(); ++i) {
    const int j = IndexOf(from, to[i]);
    if (j >= 0 && j < static_cast<int>(values.size())) (*out)[i] = values[j];
  }
}

}  // namespace

WorldLayout LayoutOf(const WorldDesc& world) {
  WorldLayout layout;
  for (const TerrainDesc& terrain : world.terrains) layout.terrains.push_back(terrain.uid);
  for (const RigidObjectDesc& object : world.objects) layout.objects.push_back(object.uid);
  for (const RobotDesc& robot : world.robots) {
    layout.robots.push_back(robot.uid);
    layout.robot_links.push_back(robot.dof());
  }
  return layout;
}

std::vector<int> MapWorldIds(const WorldLayout& from, const WorldLayout& to) {
  std::map<BodyKey, int> to_ids;
  const std::vector<BodyKey> to_keys = KeysOf(to);
  for (size_t id = 0; id < to_keys.size(); ++id) to_ids[to_keys[id]] = static_cast<int>(id);
  std::vector<int> id_map;
  for (const BodyKey& key : KeysOf(from)) {
    const auto found = to_ids.find(key);
    id_map.push_back(found == to_ids.end() ? -1 : found->second);
  }
  return id_map;
}

SimState CarryState(const WorldLayout& from, const SimState& state, const WorldLayout& to,
                    const std::vector<bool>& moves, SimState to_initial) {
  SimState out = std::move(to_initial);
  out.time = state.time;
  out.last_step = state.last_step;
  CarryByUid(from.objects, state.objects, to.objects, &out.objects);
  CarryByUid(from.objects, state.sleep, to.objects, &out.sleep);
  CarryByUid(from.robots, state.robots, to.robots, &out.robots);
  out.anchors = CarryAnchors(MapWorldIds(from, to), moves, state.anchors);
  return out;
}

std::vector<std::pair<int, int>> CarryPairs(const std::vector<int>& id_map,
                                            const std::vector<std::pair<int, int>>& pairs) {
  std::vector<std::pair<int, int>> carried;
  for (const auto& [a, b] : pairs) {
    const int new_a = MapId(id_map, a), new_b = MapId(id_map, b);
    if (new_a >= 0 && new_b >= 0)
      carried.emplace_back(std::min(new_a, new_b), std::max(new_a, new_b));
  }
  std::sort(carried.begin(), carried.end());
  return carried;
}

}  // namespace lamina::core
