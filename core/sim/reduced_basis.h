// SPDX-License-Identifier: MIT
// The velocities an island's bodies can take without opening a joint of its robots: every body
// velocity as a linear map v_k = S_k u of the island's generalized velocities u (a free body's
// six, one rate per hinge or slider). The Newton solver's reduced step (newton_solver.h,
// SolveReduced) minimizes the same row law over u instead of over every body's velocity: the
// joints' own rows (five per hinge or slider) are gone, and what is left to factor is the
// generalized mass matrix Sᵀ M S plus the rows of motors, stops and contacts (ATHLETE: 42
// unknowns instead of 258, and none of its 180 joint rows).
//
// The map is that of the configuration at the start of the step (the axes and anchors as they
// are then); what a step leaves of a joint's drift (the bodies integrate their own velocities) is
// removed after it by placing the bodies on their joints (OdeRobot::ProjectOntoJoints).
//
// Units: m, rad, s; velocities linear (the centre of mass) then angular, world axes, as in
// newton_solver.h; a hinge's rate in rad/s, a slider's in m/s (the child relative to the parent,
// along the axis).
#pragma once

#include <string>
#include <vector>

#include "core/math_types.h"

namespace lamina::core {

using Vec6 = Eigen::Matrix<double, 6, 1>;

/// How an island body moves relative to its parent body.
struct TreeLink {
  enum class Kind {
    kFree,    ///< six velocities of its own (no parent)
    kHinge,   ///< turns about `axis` through `anchor` relative to `parent`
    kSlider,  ///< slides along `axis` relative to `parent`
  };
  Kind kind = Kind::kFree;
  int parent = -1;             ///< island body index, -1: the fixed world (hinge and slider only)
  Vec3 axis = Vec3::UnitZ();   ///< unit, world axes
  Vec3 anchor = Vec3::Zero();  ///< a point on a hinge's axis (m, world)
};

/// A hinge or slider between island bodies `first` and `second` (-1: the fixed world): its kind,
/// axis and anchor as a TreeLink (whose `parent` OrientTree sets).
struct TreeEdge {
  int first = -1;
  int second = -1;
  TreeLink link;
};

/// Every one of `bodies` bodies' link to its parent (a body no edge makes a child is free) and
/// `child_edge[k]`, the edge that makes body k a child (-1: none). The edges as given, each
/// first body the child of the second, when that gives no body two parents (a robot's joints);
/// otherwise from the fixed world outwards and then from a body of each remaining part (the
/// world's joints, listed in any order and either way round). False when the edges close a loop
/// that way (as given, ReducedBasis::Build finds a loop).
bool OrientTree(int bodies, const std::vector<TreeEdge>& edges, std::vector<TreeLink>* links,
                std::vector<int>* child_edge);

class ReducedBasis {
 public:
  using Block = Eigen::Matrix<double, 6, Eigen::Dynamic>;

  /// Builds the map for bodies with centres of mass `centres` (m, world) and one TreeLink each.
  /// False, with `why` set, when the links do not form a forest (a cycle, a parent out of range,
  /// a free body with a parent).
  bool Build(const std::vector<Vec3>& centres, const std::vector<TreeLink>& links,
             std::string* why);
  Eigen::Index size() const { return size_; }
  int bodies() const { return static_cast<int>(columns_.size()); }
  /// The generalized velocities body k's velocity depends on (its own and its ancestors'), and
  /// the 6 × columns(k).size() block of S over them.
  const std::vector<int>& columns(int k) const { return columns_[k]; }
  const Block& block(int k) const { return blocks_[k]; }
  /// The generalized velocity before `column` on its body's path to the root (-1: none): each
  /// body's columns are its path, so Sᵀ M S only couples a column with those on this chain (a
  /// tree's sparsity, which a factorization from the leaves keeps: newton_solver.cpp).
  int parent_column(int column) const { return parent_column_[column]; }
  /// The bodies, every one after its parent.
  const std::vector<int>& order() const { return order_; }
  /// Body k's parent body (-1: none) and centre of mass.
  int parent(int k) const { return links_[k].parent; }
  const Vec3& centre(int k) const { return centres_[k]; }
  /// How many of body k's columns are its own (the last ones: 6 for a free body, 1 for a joint).
  int own_columns(int k) const { return links_[k].kind == TreeLink::Kind::kFree ? 6 : 1; }
  /// v_k = S_k u.
  Vec6 Velocity(int k, const VecX& u) const;
  /// The u whose S u is `velocity(k)` for every body k where the velocities keep every joint
  /// (otherwise a near one): a free body's own six, a hinge's ω_k − ω_parent along its axis, a
  /// slider's v_k − (v_parent + ω_parent × (c_k − c_parent)) along its axis.
  template <class Velocity>
  void Coordinates(Velocity velocity, VecX* u) const {
    u->resize(size_);
    for (int k : order_) {
      const Vec6 v = velocity(k);
      const TreeLink& link = links_[k];
      const int own = columns_[k].back();
      if (link.kind == TreeLink::Kind::kFree) {
        u->segment<6>(own - 5) = v;
        continue;
      }
      const Vec6 parent = link.parent >= 0 ? Vec6(velocity(link.parent)) : Vec6(Vec6::Zero());
      if (link.kind == TreeLink::Kind::kHinge) {
        (*u)[own] = link.axis.dot(v.tail<3>() - parent.tail<3>());
      } else {
        const Vec3 arm =
            link.parent >= 0 ? Vec3(centres_[k] - centres_[link.parent]) : Vec3::Zero();
        const Vec3 carried = parent.head<3>() + parent.tail<3>().cross(arm);
        (*u)[own] = link.axis.dot(v.head<3>() - carried);
      }
    }
  }

 private:
  bool Order(const std::vector<TreeLink>& links, std::string* why);
  void AddBody(int k, const std::vector<Vec3>& centres, const TreeLink& link);

  Eigen::Index size_ = 0;
  std::vector<int> order_;  ///< parents before children
  std::vector<TreeLink> links_;
  std::vector<Vec3> centres_;
  std::vector<int> parent_column_;
  std::vector<std::vector<int>> columns_;
  std::vector<Block> blocks_;
};

}  // namespace lamina::core
