// SPDX-License-Identifier: MIT
// Deterministic k-means reduction of a pair's contacts (see contact_clustering.h). The working
// buffers live in a per-thread workspace so that the per-step calls of the simulator do not
// allocate once the buffers have grown to the largest pair seen.
#include "core/contact/contact_clustering.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace lamina::core {
namespace {

/// (x, y, z, s nx, s ny, s nz, depth): Klamp't's clustering feature of a contact.
using Feature = Eigen::Matrix<double, 7, 1>;

constexpr int kMaxIterations = 20;
// Klamp't's subsampling guard: cluster a subsample when n * k > 5000 and n * n > 2000, of
// max(5000 / k, floor(sqrt(2000)) = 44) contacts.
constexpr std::size_t kSubsampleWorkLimit = 5000;
constexpr std::size_t kSubsampleSquareLimit = 2000;
constexpr std::size_t kMinSubsampleSize = 44;
// contacts shallower than this (m) weigh as if this deep, so that a cluster of contacts at
// depth 0 still has a centre
constexpr double kMinPressureDepth = 1e-9;
// Below this length the mean of the members' unit normals has no usable direction (they cancel).
constexpr double kMinMeanNormalLength = 1e-6;

/// What the final assignment gathers about one cluster's members.
struct ClusterSums {
  Vec3 position_sum = Vec3::Zero();
  Vec3 weighted_position_sum = Vec3::Zero();  ///< positions times pressure weights
  double weight_sum = 0.0;
  Vec3 normal_sum = Vec3::Zero();
  std::size_t count = 0;
  double max_depth = 0.0;  ///< of the first member of maximal depth (the deepest)
  Vec3 deepest_normal = Vec3::UnitZ();
  bool penetrating = false;
};

struct Workspace {
  std::vector<Feature> features;  ///< one per input contact
  std::vector<Feature> sample;    ///< the clustered subset, when subsampling
  std::vector<Feature> centres;
  std::vector<double> nearest_squared_distances;  ///< per point, to the nearest seed so far
  std::vector<double> second_squared_distances;   ///< per point, to the second nearest seed
  std::vector<int> labels;
  // Hamerly's bounds (not squared): per point, at least as far as its own centre is and at most
  // as far as any other centre is; per centre, how far the last update moved it
  std::vector<double> upper;
  std::vector<double> lower;
  std::vector<Feature> previous_centres;
  std::vector<double> moved;
  std::vector<std::size_t> counts;
  std::vector<ClusterSums> sums;
};

Workspace& ThreadWorkspace() {
  thread_local Workspace workspace;
  return workspace;
}

Feature MakeFeature(const Contact& contact, double normal_scale) {
  Feature feature;
  feature << contact.position, normal_scale * contact.normal, contact.depth;
  return feature;
}

/// Index of the centre nearest to `point`, the lowest index on ties, with the squared distances
/// to it and to the next nearest centre (infinite with one centre). A non-finite point compares
/// false against everything and stays with centre 0.
int NearestTwoCentres(const Feature& point, const std::vector<Feature>& centres, double* best,
                      double* second) {
  int nearest = 0;
  double first = (point - centres[0]).squaredNorm(), next = kInf;
  // selects rather than branches: which centre is nearest changes unpredictably
  for (std::size_t j = 1; j < centres.size(); ++j) {
    const double distance = (point - centres[j]).squaredNorm();
    const bool nearer = distance < first;
    next = nearer ? first : std::min(next, distance);
    nearest = nearer ? static_cast<int>(j) : nearest;
    first = nearer ? distance : first;
  }
  *best = first;
  *second = next;
  return nearest;
}

int NearestCentre(const Feature& point, const std::vector<Feature>& centres) {
  double best = 0.0, second = 0.0;
  return NearestTwoCentres(point, centres, &best, &second);
}

// Relative margin by which a bound must win before a point is left with its centre: the bounds
// are sums of a few rounded distances, good to about 1e-15 of their size.
constexpr double kBoundMargin = 1e-9;

/// True when the bounds prove the point's own centre strictly nearer than every other, so that
/// NearestCentre would keep its label (a NaN bound proves nothing).
bool BoundsKeep(double upper, double lower) {
  return upper * (1.0 + kBoundMargin) < lower * (1.0 - kBoundMargin);
}

/// Labels point i afresh with its nearest centre and resets its bounds.
void Relabel(const std::vector<Feature>& points, std::size_t i, Workspace* w) {
  double best = 0.0, second = 0.0;
  w->labels[i] = NearestTwoCentres(points[i], w->centres, &best, &second);
  w->upper[i] = std::sqrt(best);
  w->lower[i] = std::sqrt(second);
}

/// Labels every point with its nearest centre, as NearestCentre would, skipping the points whose
/// bounds (Hamerly's) show their centre still nearest; true when any label changed.
bool AssignLabels(const std::vector<Feature>& points, Workspace* w) {
  const double most_moved = *std::max_element(w->moved.begin(), w->moved.end());
  bool changed = false;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const int label = w->labels[i];
    w->upper[i] += w->moved[label];
    w->lower[i] -= most_moved;
    if (BoundsKeep(w->upper[i], w->lower[i])) continue;
    w->upper[i] = (points[i] - w->centres[label]).norm();  // tightened
    if (BoundsKeep(w->upper[i], w->lower[i])) continue;
    Relabel(points, i, w);
    changed = changed || w->labels[i] != label;
  }
  return changed;
}

void CountMembers(const std::vector<int>& labels, std::vector<std::size_t>* counts) {
  std::fill(counts->begin(), counts->end(), std::size_t{0});
  for (const int label : labels) ++(*counts)[label];
}

/// Gives each empty cluster, in index order, the member of the currently largest cluster (lowest
/// index on ties) farthest from that cluster's centre (lowest point index on ties). No seed starts
/// empty (each is nearest to its own point), but a Lloyd update can still leave a cluster without
/// members in unlucky configurations. With at least as many points as clusters, an empty cluster
/// implies a cluster of two or more members, so the donor never becomes empty itself.
void ReseedEmptyClusters(const std::vector<Feature>& points, const std::vector<Feature>& centres,
                         std::vector<int>* labels, std::vector<std::size_t>* counts,
                         std::vector<double>* lower) {
  for (std::size_t empty = 0; empty < counts->size(); ++empty) {
    if ((*counts)[empty] != 0) continue;
    const auto largest =
        static_cast<int>(std::max_element(counts->begin(), counts->end()) - counts->begin());
    if ((*counts)[largest] < 2) return;
    std::size_t farthest = points.size();
    double farthest_distance = -1.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if ((*labels)[i] != largest) continue;
      const double distance = (points[i] - centres[largest]).squaredNorm();
      if (distance > farthest_distance || farthest == points.size()) {
        farthest_distance = distance;
        farthest = i;
      }
    }
    (*labels)[farthest] = static_cast<int>(empty);
    (*lower)[farthest] = 0.0;  // its old centre is another one now: labelled afresh next time
    --(*counts)[largest];
    (*counts)[empty] = 1;
  }
}

/// Moves every non-empty cluster's centre to the mean of its members, and records how far each
/// centre moved.
void UpdateCentres(const std::vector<Feature>& points, Workspace* w) {
  std::vector<Feature>& centres = w->centres;
  w->previous_centres = centres;
  for (std::size_t j = 0; j < centres.size(); ++j) {
    if (w->counts[j] != 0) centres[j].setZero();
  }
  for (std::size_t i = 0; i < points.size(); ++i) centres[w->labels[i]] += points[i];
  w->moved.resize(centres.size());
  for (std::size_t j = 0; j < centres.size(); ++j) {
    if (w->counts[j] != 0) centres[j] /= static_cast<double>(w->counts[j]);
    w->moved[j] = (centres[j] - w->previous_centres[j]).norm();
  }
}

/// Brings every point's nearest seed (distance and label) up to date with the newest centre.
/// A label changes only on a strictly nearer centre, so ties keep the lowest index and a
/// non-finite point keeps centre 0, as in NearestCentre.
void CompareWithNewestCentre(const std::vector<Feature>& points, Workspace* workspace) {
  const Feature& centre = workspace->centres.back();
  const int label = static_cast<int>(workspace->centres.size()) - 1;
  std::vector<double>& nearest = workspace->nearest_squared_distances;
  std::vector<double>& second = workspace->second_squared_distances;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double distance = (points[i] - centre).squaredNorm();
    if (distance < nearest[i]) {
      second[i] = nearest[i];
      nearest[i] = distance;
      workspace->labels[i] = label;
    } else if (!(distance >= nearest[i])) {
      nearest[i] = distance;  // a NaN distance (a non-finite contact) sticks and never wins
    } else if (distance < second[i]) {
      second[i] = distance;
    }
  }
}

/// Farthest-point seeding: centre 0 is point 0 and each further centre is the point farthest
/// from the centres chosen so far (lowest index on ties), so the centres start spread over the
/// whole input whatever its order. Stops early when every point coincides with a centre (fewer
/// distinct contacts than clusters). Leaves each point labelled with its nearest centre, as
/// AssignLabels would.
void SeedCentres(const std::vector<Feature>& points, std::size_t cluster_count,
                 Workspace* workspace) {
  std::vector<Feature>& centres = workspace->centres;
  const std::vector<double>& nearest = workspace->nearest_squared_distances;
  centres.assign(1, points[0]);
  workspace->nearest_squared_distances.assign(points.size(), kInf);
  workspace->second_squared_distances.assign(points.size(), kInf);
  workspace->labels.assign(points.size(), 0);
  CompareWithNewestCentre(points, workspace);
  while (centres.size() < cluster_count) {
    std::size_t farthest = 0;
    double farthest_distance = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (nearest[i] > farthest_distance) {
        farthest_distance = nearest[i];
        farthest = i;
      }
    }
    if (farthest_distance == 0.0) return;
    centres.push_back(points[farthest]);
    CompareWithNewestCentre(points, workspace);
  }
}

/// Lloyd's algorithm on `points` from farthest-point seeds (whose labels make the first
/// assignment); leaves the final centres in the workspace. True when it converged: the labels
/// are then every point's nearest final centre.
bool RunKMeans(const std::vector<Feature>& points, std::size_t cluster_count,
               Workspace* workspace) {
  SeedCentres(points, cluster_count, workspace);
  workspace->counts.resize(workspace->centres.size());
  workspace->upper.resize(points.size());
  workspace->lower.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    workspace->upper[i] = std::sqrt(workspace->nearest_squared_distances[i]);
    workspace->lower[i] = std::sqrt(workspace->second_squared_distances[i]);
  }
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    if (iteration > 0 && !AssignLabels(points, workspace)) return true;
    CountMembers(workspace->labels, &workspace->counts);
    ReseedEmptyClusters(points, workspace->centres, &workspace->labels, &workspace->counts,
                        &workspace->lower);
    UpdateCentres(points, workspace);
  }
  return false;
}

/// The features to cluster: all of them, or a uniform-stride subsample (index floor(i n / m))
/// of m = max(5000 / k, 44, k) when the input is very large.
const std::vector<Feature>& PointsToCluster(std::size_t cluster_count, Workspace* workspace) {
  const std::size_t n = workspace->features.size();
  if (n * cluster_count <= kSubsampleWorkLimit || n * n <= kSubsampleSquareLimit) {
    return workspace->features;
  }
  const std::size_t m =
      std::max({kSubsampleWorkLimit / cluster_count, kMinSubsampleSize, cluster_count});
  workspace->sample.resize(m);
  for (std::size_t i = 0; i < m; ++i) workspace->sample[i] = workspace->features[i * n / m];
  return workspace->sample;
}

/// Assigns every contact to its nearest final centre and gathers the members' sums. With
/// `labelled`, workspace->labels already hold each contact's nearest final centre.
void GatherClusters(const ContactList& contacts, bool labelled, Workspace* workspace) {
  workspace->sums.assign(workspace->centres.size(), ClusterSums{});
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& contact = contacts[i];
    const int label =
        labelled ? workspace->labels[i] : NearestCentre(workspace->features[i], workspace->centres);
    ClusterSums& sums = workspace->sums[label];
    if (sums.count == 0 || contact.depth > sums.max_depth) {
      sums.max_depth = contact.depth;
      sums.deepest_normal = contact.normal;
    }
    const double weight = PressureWeight(contact, kMinPressureDepth);
    sums.position_sum += contact.position;
    sums.weighted_position_sum += weight * contact.position;
    sums.weight_sum += weight;
    sums.normal_sum += contact.normal;
    sums.penetrating = sums.penetrating || contact.penetrating;
    ++sums.count;
  }
}

Contact SummarizeCluster(const ClusterSums& sums) {
  const double count = static_cast<double>(sums.count);
  const Vec3 mean_normal = sums.normal_sum / count;
  const double length = mean_normal.norm();
  Contact out;
  // the centre of the members' pressure, so that a cluster pushes where its members would
  // (a plain centroid moves the pair's centre of pressure, and a symmetric patch reduced to
  // asymmetric clusters would twist the body)
  out.position = sums.weight_sum > 0.0 ? Vec3(sums.weighted_position_sum / sums.weight_sum)
                                       : Vec3(sums.position_sum / count);
  out.weight = sums.weight_sum;
  out.normal = length > kMinMeanNormalLength ? Vec3(mean_normal / length) : sums.deepest_normal;
  out.depth = sums.max_depth;
  out.penetrating = sums.penetrating;
  return out;
}

}  // namespace

void ClusterContacts(int max_contacts, double normal_scale, ContactList* contacts) {
  if (max_contacts <= 0) {
    contacts->clear();
    return;
  }
  const auto cluster_count = static_cast<std::size_t>(max_contacts);
  if (contacts->size() <= cluster_count) return;
  Workspace& workspace = ThreadWorkspace();
  workspace.features.resize(contacts->size());
  for (std::size_t i = 0; i < contacts->size(); ++i) {
    workspace.features[i] = MakeFeature((*contacts)[i], normal_scale);
  }
  const std::vector<Feature>& points = PointsToCluster(cluster_count, &workspace);
  const bool converged = RunKMeans(points, cluster_count, &workspace);
  // the final labels serve the gathering when every contact was clustered
  GatherClusters(*contacts, converged && &points == &workspace.features, &workspace);
  // The outputs overwrite the front of the list: the sums hold everything they need.
  std::size_t output_count = 0;
  for (const ClusterSums& sums : workspace.sums) {
    if (sums.count != 0) (*contacts)[output_count++] = SummarizeCluster(sums);
  }
  contacts->resize(output_count);
}

}  // namespace lamina::core

namespace lamina::core {
namespace {

// cos(15 degrees)
constexpr double kSameNormal = 0.9659258262890683;
// below this many contacts the plain scan over the survivors is as fast as the grid
constexpr std::size_t kMergeGridMinimum = 32;

bool Coincide(const Contact& survivor, const Contact& contact, double radius_squared) {
  // written so that NaN compares as coinciding, as it always has
  return !((survivor.position - contact.position).squaredNorm() > radius_squared) &&
         !(survivor.normal.dot(contact.normal) < kSameNormal);
}

void Absorb(const Contact& contact, Contact* survivor) {
  survivor->depth = std::max(survivor->depth, contact.depth);
  survivor->penetrating = survivor->penetrating || contact.penetrating;
}

// Index of the first survivor (of contacts[0, kept)) that `contact` coincides with; kept if none.
std::size_t FirstCoincident(const ContactList& contacts, std::size_t kept, const Contact& contact,
                            double radius_squared) {
  for (std::size_t k = 0; k < kept; ++k) {
    if (Coincide(contacts[k], contact, radius_squared)) return k;
  }
  return kept;
}

void MergeByScan(double radius_squared, ContactList* contacts) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < contacts->size(); ++i) {
    const Contact contact = (*contacts)[i];
    const std::size_t k = FirstCoincident(*contacts, kept, contact, radius_squared);
    if (k < kept) {
      Absorb(contact, &(*contacts)[k]);
    } else {
      (*contacts)[kept++] = contact;
    }
  }
  contacts->resize(kept);
}

using Cell = Eigen::Matrix<std::int64_t, 3, 1>;

// Edge of the survivor grid's cells, in merge radii. A survivor's radius-ball overlaps two
// cells along an axis with probability 2/kCellRadii, so it is entered in (1 + 2/4)^3 = 3.4
// cells on average instead of 8 with cells of two radii; a cell then holds more survivors to
// compare, but survivors whose normals agree are at least a radius apart.
constexpr double kCellRadii = 4.0;

// The survivors hashed into a grid of cells of edge kCellRadii·radius: each survivor is entered
// in every cell its radius-ball overlaps (at most 2 per axis, 8 in all), so a contact finds every
// survivor within radius of it in its own cell, with one lookup. Open addressing over the cells
// in use (at most half the slots: the table doubles beyond); each slot heads a chain of entries.
// Kept per thread, and only its used slots emptied, so that a call neither allocates once grown
// nor costs more than its contacts.
class SurvivorGrid {
 public:
  void Reset(double radius) {
    for (const std::size_t slot : used_) slots_[slot].head = -1;
    if (slots_.empty()) Resize(64);
    used_.clear();
    entries_.clear();
    radius_ = radius;
    inverse_edge_ = 1.0 / (kCellRadii * radius);
  }

  // the first survivor within radius_squared of `contact` (normals agreeing), or -1
  int FirstCoincident(const ContactList& survivors, const Contact& contact,
                      double radius_squared) const {
    const std::size_t slot = Find(CellOf(contact.position));
    int first = -1;
    for (int e = slots_[slot].head; e >= 0; e = entries_[e].next) {
      const int k = entries_[e].survivor;
      if ((first < 0 || k < first) && Coincide(survivors[k], contact, radius_squared)) first = k;
    }
    return first;
  }

  void Add(int survivor, const Vec3& position) {
    const Cell low = CellOf(position - Vec3::Constant(radius_));
    const Cell high = CellOf(position + Vec3::Constant(radius_));
    for (std::int64_t x = low.x(); x <= high.x(); ++x) {
      for (std::int64_t y = low.y(); y <= high.y(); ++y) {
        for (std::int64_t z = low.z(); z <= high.z(); ++z) Enter(survivor, Cell(x, y, z));
      }
    }
  }

 private:
  struct Slot {
    Cell cell;
    int head = -1;  ///< the cell's latest entry, -1 for an empty slot
  };
  struct Entry {
    int survivor;
    int next;  ///< the cell's previous entry, -1 at the end
  };

  Cell CellOf(const Vec3& position) const {
    const Vec3 scaled = position * inverse_edge_;
    return Cell(FloorIndex(scaled.x()), FloorIndex(scaled.y()), FloorIndex(scaled.z()));
  }

  // floor(x) for |x| < 2^52 (GridFits), by truncation: std::floor without SSE4.1 is a longer
  // sequence, and a cell is found three times for each contact
  static std::int64_t FloorIndex(double x) {
    const auto truncated = static_cast<std::int64_t>(x);
    return truncated - (x < static_cast<double>(truncated) ? 1 : 0);
  }

  void Enter(int survivor, const Cell& cell) {
    std::size_t slot = Find(cell);
    if (slots_[slot].head < 0) {
      if (2 * (used_.size() + 1) > slots_.size()) {
        Resize(2 * slots_.size());
        slot = Find(cell);
      }
      used_.push_back(slot);
      slots_[slot].cell = cell;
    }
    entries_.push_back({survivor, slots_[slot].head});
    slots_[slot].head = static_cast<int>(entries_.size()) - 1;
  }

  // Rehashes the cells in use into `size` slots (a power of two).
  void Resize(std::size_t size) {
    std::vector<Slot> old(size);
    old.swap(slots_);
    shift_ = 64;
    for (std::size_t n = size; n > 1; n /= 2) --shift_;
    for (std::size_t& slot : used_) {
      const std::size_t moved = Find(old[slot].cell);
      slots_[moved] = old[slot];
      slot = moved;
    }
  }

  // The slot of `cell`, or the empty slot where it would go. The cell's coordinates are mixed
  // and the product's high bits taken (Fibonacci hashing): the low bits of a xor of products
  // repeat across a patch's neighbouring cells and make long probe runs. The slots do not
  // change the result, only how fast it is found.
  std::size_t Find(const Cell& cell) const {
    const std::uint64_t key = static_cast<std::uint64_t>(cell.x()) * 73856093ULL ^
                              static_cast<std::uint64_t>(cell.y()) * 19349663ULL ^
                              static_cast<std::uint64_t>(cell.z()) * 83492791ULL;
    const std::size_t mask = slots_.size() - 1;
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >> shift_);
    while (slots_[slot].head >= 0 && slots_[slot].cell != cell) slot = (slot + 1) & mask;
    return slot;
  }

  std::vector<Slot> slots_;
  std::vector<Entry> entries_;
  std::vector<std::size_t> used_;  ///< the slots holding a cell
  int shift_ = 58;                 ///< 64 - log2(slot count)
  double radius_ = 1.0;
  double inverse_edge_ = 1.0 / kCellRadii;
};

// Same result as MergeByScan (each contact joins the FIRST survivor it coincides with), in
// O(n) for contacts spread over the patch instead of O(n · survivors).
void MergeByGrid(double radius, ContactList* contacts) {
  thread_local SurvivorGrid grid;
  grid.Reset(radius);
  const double radius_squared = radius * radius;
  int kept = 0;
  for (std::size_t i = 0; i < contacts->size(); ++i) {
    const Contact contact = (*contacts)[i];
    const int k = grid.FirstCoincident(*contacts, contact, radius_squared);
    if (k >= 0) {
      Absorb(contact, &(*contacts)[k]);
    } else {
      (*contacts)[kept] = contact;
      grid.Add(kept++, contact.position);
    }
  }
  contacts->resize(kept);
}

// The grid needs cell indices that fit: finite positions within 2^52 radii of the origin.
bool GridFits(double radius, const ContactList& contacts) {
  if (!(radius > 0.0) || !std::isfinite(radius)) return false;
  const double limit = 4.5e15 * radius;
  return std::all_of(contacts.begin(), contacts.end(), [limit](const Contact& c) {
    return c.position.allFinite() && c.position.cwiseAbs().maxCoeff() < limit;
  });
}

}  // namespace

void MergeCoincidentContacts(double radius, ContactList* contacts) {
  if (contacts->size() >= kMergeGridMinimum && GridFits(radius, *contacts)) {
    MergeByGrid(radius, contacts);
  } else {
    MergeByScan(radius * radius, contacts);
  }
}

}  // namespace lamina::core
