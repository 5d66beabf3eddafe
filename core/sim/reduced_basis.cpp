// SPDX-License-Identifier: MIT
#include "core/sim/reduced_basis.h"

#include <algorithm>

namespace lamina::core {

namespace {

void MakeChild(const std::vector<TreeEdge>& edges, int e, int child, int parent,
               std::vector<TreeLink>* links, std::vector<int>* child_edge) {
  TreeLink& link = (*links)[child];
  link = edges[e].link;
  link.parent = parent;
  (*child_edge)[child] = e;
}

bool OrientAsGiven(const std::vector<TreeEdge>& edges, std::vector<TreeLink>* links,
                   std::vector<int>* child_edge) {
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    if ((*child_edge)[edges[e].first] >= 0) return false;
    MakeChild(edges, e, edges[e].first, edges[e].second, links, child_edge);
  }
  return true;
}

// breadth first from the bodies reached so far (`queue`), each edge used once; false when an
// edge meets a body already reached (a loop)
bool Spread(const std::vector<TreeEdge>& edges, std::vector<int>* queue, std::vector<char>* used,
            std::vector<TreeLink>* links, std::vector<int>* child_edge) {
  for (size_t i = 0; i < queue->size(); ++i) {
    const int k = (*queue)[i];
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
      const TreeEdge& edge = edges[e];
      if ((*used)[e] || (edge.first != k && edge.second != k)) continue;
      (*used)[e] = 1;
      const int other = edge.first == k ? edge.second : edge.first;
      if (other < 0 || std::find(queue->begin(), queue->end(), other) != queue->end()) {
        return false;
      }
      MakeChild(edges, e, other, k, links, child_edge);
      queue->push_back(other);
    }
  }
  return true;
}

bool OrientFromWorld(const std::vector<TreeEdge>& edges, std::vector<TreeLink>* links,
                     std::vector<int>* child_edge) {
  std::vector<char> used(edges.size(), 0);
  std::vector<int> queue;
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    if (edges[e].second >= 0) continue;
    if ((*child_edge)[edges[e].first] >= 0) return false;  // held by the world twice
    MakeChild(edges, e, edges[e].first, -1, links, child_edge);
    used[e] = 1;
    queue.push_back(edges[e].first);
  }
  for (size_t e = 0;; ++e) {
    if (!Spread(edges, &queue, &used, links, child_edge)) return false;
    while (e < edges.size() && used[e]) ++e;
    if (e == edges.size()) return true;
    queue.push_back(std::min(edges[e].first, edges[e].second));  // a free root
  }
}

}  // namespace

bool OrientTree(int bodies, const std::vector<TreeEdge>& edges, std::vector<TreeLink>* links,
                std::vector<int>* child_edge) {
  links->assign(static_cast<size_t>(bodies), TreeLink{});
  child_edge->assign(static_cast<size_t>(bodies), -1);
  if (OrientAsGiven(edges, links, child_edge)) return true;
  links->assign(static_cast<size_t>(bodies), TreeLink{});
  child_edge->assign(static_cast<size_t>(bodies), -1);
  return OrientFromWorld(edges, links, child_edge);
}

bool ReducedBasis::Build(const std::vector<Vec3>& centres, const std::vector<TreeLink>& links,
                         std::string* why) {
  const int count = static_cast<int>(links.size());
  columns_.resize(count);
  blocks_.resize(count);
  size_ = 0;
  if (centres.size() != links.size()) {
    *why = "one centre of mass per body is needed";
    return false;
  }
  if (!Order(links, why)) return false;
  links_ = links;
  centres_ = centres;
  parent_column_.clear();
  for (int k : order_) AddBody(k, centres, links[k]);
  return true;
}

// order_: every body after its parent (by depth); false for a cycle or a bad parent
bool ReducedBasis::Order(const std::vector<TreeLink>& links, std::string* why) {
  const int count = static_cast<int>(links.size());
  std::vector<int> depth(count, 0);
  for (int k = 0; k < count; ++k) {
    const TreeLink& link = links[k];
    if (link.kind == TreeLink::Kind::kFree && link.parent >= 0) {
      *why = "body " + std::to_string(k) + " is free but has a parent";
      return false;
    }
    int steps = 0;
    for (int p = link.parent; p >= 0; p = links[p].parent) {
      if (p >= count || ++steps > count) {
        *why = "body " + std::to_string(k) + "'s parents do not end at a root (a loop)";
        return false;
      }
    }
    depth[k] = steps;
  }
  order_.resize(count);
  for (int k = 0; k < count; ++k) order_[k] = k;
  std::stable_sort(order_.begin(), order_.end(), [&](int x, int y) { return depth[x] < depth[y]; });
  return true;
}

// body k's columns: its parent's, moved to k's centre, then its own
void ReducedBasis::AddBody(int k, const std::vector<Vec3>& centres, const TreeLink& link) {
  std::vector<int>& columns = columns_[k];
  Block& block = blocks_[k];
  if (link.kind == TreeLink::Kind::kFree) {
    columns.resize(6);
    for (int c = 0; c < 6; ++c) {
      columns[c] = static_cast<int>(size_ + c);
      parent_column_.push_back(c == 0 ? -1 : columns[c] - 1);
    }
    block = Eigen::Matrix<double, 6, 6>::Identity();
    size_ += 6;
    return;
  }
  const int p = link.parent;
  const Eigen::Index inherited = p >= 0 ? static_cast<Eigen::Index>(columns_[p].size()) : 0;
  columns.clear();
  if (p >= 0) columns = columns_[p];
  parent_column_.push_back(p >= 0 ? columns_[p].back() : -1);
  columns.push_back(static_cast<int>(size_++));
  block.resize(6, inherited + 1);
  if (p >= 0) {
    const Block& parent = blocks_[p];
    const Vec3 arm = centres[k] - centres[p];
    for (Eigen::Index c = 0; c < inherited; ++c) {  // v_k = v_p + ω_p × (c_k − c_p)
      const Vec3 omega = parent.col(c).tail<3>();
      block.col(c).head<3>() = parent.col(c).head<3>() + omega.cross(arm);
      block.col(c).tail<3>() = omega;
    }
  }
  Vec6 own = Vec6::Zero();
  if (link.kind == TreeLink::Kind::kHinge) {
    own << link.axis.cross(centres[k] - link.anchor), link.axis;
  } else {
    own.head<3>() = link.axis;
  }
  block.col(inherited) = own;
}

Vec6 ReducedBasis::Velocity(int k, const VecX& u) const {
  const std::vector<int>& columns = columns_[k];
  Vec6 v = Vec6::Zero();
  for (size_t c = 0; c < columns.size(); ++c) v += blocks_[k].col(c) * u[columns[c]];
  return v;
}

}  // namespace lamina::core
