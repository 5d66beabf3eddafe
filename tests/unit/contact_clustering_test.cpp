// SPDX-License-Identifier: MIT
// Contact clustering: small inputs untouched, tight groups reduced to their centroids with the
// deepest depth, determinism, deterministic re-seeding of empty clusters, the normal fallback,
// and large inputs (uniform-stride subsample, every contact assigned to the final centres).
#include "core/contact/contact_clustering.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

namespace lamina::core {
namespace {

// Means of a handful of values of order 1: a few ulps of rounding.
constexpr double kMeanTolerance = 1e-12;

Contact MakeContact(const Vec3& position, const Vec3& normal, double depth,
                    bool penetrating = false) {
  Contact contact;
  contact.position = position;
  contact.normal = normal;
  contact.depth = depth;
  contact.penetrating = penetrating;
  return contact;
}

void ExpectIdentical(const ContactList& actual, const ContactList& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(actual[i].position, expected[i].position);
    EXPECT_EQ(actual[i].normal, expected[i].normal);
    EXPECT_EQ(actual[i].depth, expected[i].depth);
    EXPECT_EQ(actual[i].penetrating, expected[i].penetrating);
  }
}

// A `columns` x `rows` grid of upward contacts with 1 cm spacing in the plane z = 0, listed row
// by row (x fastest), as a mesh lying on a floor produces them.
ContactList Grid(int columns, int rows) {
  ContactList contacts;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      contacts.push_back(MakeContact(Vec3(0.01 * column, 0.01 * row, 0.0), Vec3::UnitZ(), 1e-3));
    }
  }
  return contacts;
}

TEST(ContactClusteringTest, AtMostMaxContactsAreLeftUntouched) {
  const ContactList original = {
      MakeContact(Vec3(0.1, 0.2, 0.3), Vec3(0.6, 0.0, 0.8), 1e-3, true),
      MakeContact(Vec3(-1.0, 0.0, 2.0), Vec3(0.0, 1.0, 0.0), 2e-3),
      MakeContact(Vec3(1.0 / 3.0, 1e-17, 5.0), Vec3(0.0, 0.0, -1.0), 0.0)};
  for (const int max_contacts : {3, 4, 20}) {
    SCOPED_TRACE(max_contacts);
    ContactList contacts = original;
    ClusterContacts(max_contacts, kDefaultClusterNormalScale, &contacts);
    ExpectIdentical(contacts, original);
  }
}

TEST(ContactClusteringTest, ZeroMaxContactsLeavesNone) {
  ContactList contacts = Grid(3, 1);
  ClusterContacts(0, kDefaultClusterNormalScale, &contacts);
  EXPECT_TRUE(contacts.empty());
}

// Four groups 1 m apart, each of a few contacts spread by a millimetre, listed interleaved (as
// an aggregated list of several feet would be): one output per group, at the group's centroid,
// with its deepest depth. Seeding from the contacts at indices floor(i n / k) (Klamp't) would
// put two seeds in group 0 here (indices 0 and 4) and end with one output straddling two groups.
TEST(ContactClusteringTest, TightGroupsReduceToTheirCentresOfPressure) {
  const std::vector<Vec3> group_centres = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                           Vec3(1, 1, 0.5)};
  const std::vector<int> group_sizes = {3, 5, 4, 6};
  std::vector<ContactList> groups(group_centres.size());
  for (std::size_t g = 0; g < group_centres.size(); ++g) {
    for (int i = 0; i < group_sizes[g]; ++i) {
      const Vec3 offset(1e-3 * i, -5e-4 * (i % 2), 2e-4 * i);
      const Vec3 normal = Vec3(0.02 * (i % 3), -0.01 * i, 1.0).normalized();
      const bool penetrating = (g == 2 && i == 1);
      groups[g].push_back(
          MakeContact(group_centres[g] + offset, normal, 1e-3 * ((i * 7) % 5), penetrating));
    }
  }
  ContactList contacts;
  for (int i = 0; i < 6; ++i) {
    for (const ContactList& group : groups) {
      if (i < static_cast<int>(group.size())) contacts.push_back(group[i]);
    }
  }
  ClusterContacts(4, kDefaultClusterNormalScale, &contacts);
  ASSERT_EQ(contacts.size(), 4u);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    SCOPED_TRACE(g);
    // the members' positions weighted by depth² (a member at depth 0 weighs (1e-9)²)
    Vec3 weighted_sum = Vec3::Zero();
    double weight_sum = 0.0;
    Vec3 normal_sum = Vec3::Zero();
    double max_depth = 0.0;
    for (const Contact& member : groups[g]) {
      const double depth = std::max(member.depth, 1e-9);
      weighted_sum += depth * depth * member.position;
      weight_sum += depth * depth;
      normal_sum += member.normal;
      max_depth = std::max(max_depth, member.depth);
    }
    const Vec3 centroid = weighted_sum / weight_sum;
    const auto output = std::find_if(contacts.begin(), contacts.end(), [&](const Contact& c) {
      return (c.position - centroid).norm() <= kMeanTolerance;
    });
    ASSERT_TRUE(output != contacts.end()) << "no output at " << centroid.transpose();
    EXPECT_LE((output->normal - normal_sum.normalized()).norm(), kMeanTolerance);
    EXPECT_EQ(output->depth, max_depth);
    EXPECT_NEAR(output->weight, weight_sum, 1e-15);
    EXPECT_EQ(output->penetrating, g == 2);
  }
}

// The fallback: a unit normal averaged with its opposite has no direction; the deepest member's
// normal is the one that should push the bodies apart.
TEST(ContactClusteringTest, OppositeNormalsFallBackToTheDeepestNormal) {
  ContactList contacts = {MakeContact(Vec3(0, 0, 0), Vec3::UnitZ(), 1e-3),
                          MakeContact(Vec3(0, 0, 0.002), -Vec3::UnitZ(), 3e-3),
                          MakeContact(Vec3(0, 0, 0.004), Vec3::UnitZ(), 2e-3),
                          MakeContact(Vec3(0, 0, 0.006), -Vec3::UnitZ(), 3e-3)};
  ClusterContacts(1, kDefaultClusterNormalScale, &contacts);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].normal, -Vec3::UnitZ());
  EXPECT_EQ(contacts[0].depth, 3e-3);
  // centre of pressure: depths 1, 3, 2, 3 mm weigh 1, 9, 4, 9 at z = 0, 2, 4, 6 mm
  const double z = (9 * 0.002 + 4 * 0.004 + 9 * 0.006) / 23.0;
  EXPECT_LE((contacts[0].position - Vec3(0, 0, z)).norm(), kMeanTolerance);
}

TEST(ContactClusteringTest, MeanNormalIsRenormalized) {
  const double half = 0.5 * std::sqrt(2.0);
  ContactList contacts = {MakeContact(Vec3(0, 0, 0), Vec3(half, 0, half), 1e-3),
                          MakeContact(Vec3(0, 0, 0), Vec3(-half, 0, half), 1e-3)};
  ClusterContacts(1, kDefaultClusterNormalScale, &contacts);
  ASSERT_EQ(contacts.size(), 1u);
  // One rounding in the sum and one in the normalization.
  EXPECT_LE((contacts[0].normal - Vec3::UnitZ()).norm(), 1e-15);
}

// Exact duplicates (adjacent triangles reporting the same vertex): two distinct contacts, three
// copies each (one copy flagged penetrating), and room for four clusters: two outputs, never two
// at the same place. Outputs come in cluster order; the seeds are contact 0 (a) and then the
// contact farthest from it (b).
TEST(ContactClusteringTest, DuplicateContactsMerge) {
  const Contact a = MakeContact(Vec3(0.1, 0.2, 0.0), Vec3::UnitZ(), 2e-3);
  const Contact b = MakeContact(Vec3(0.4, 0.2, 0.0), Vec3::UnitX(), 1e-3);
  ContactList contacts = {a, b, a, b, a, b};
  contacts[3].penetrating = true;
  ClusterContacts(4, kDefaultClusterNormalScale, &contacts);
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_LE((contacts[0].position - a.position).norm(), kMeanTolerance);
  EXPECT_EQ(contacts[0].normal, a.normal);
  EXPECT_EQ(contacts[0].depth, a.depth);
  EXPECT_FALSE(contacts[0].penetrating);
  EXPECT_LE((contacts[1].position - b.position).norm(), kMeanTolerance);
  EXPECT_EQ(contacts[1].normal, b.normal);
  EXPECT_EQ(contacts[1].depth, b.depth);
  EXPECT_TRUE(contacts[1].penetrating);
}

TEST(ContactClusteringTest, SameInputGivesTheSameOutput) {
  ContactList input = Grid(60, 50);
  for (std::size_t i = 0; i < input.size(); ++i) input[i].depth = 1e-4 * static_cast<double>(i % 7);
  ContactList first = input;
  ClusterContacts(20, kDefaultClusterNormalScale, &first);
  // A different call in between: the reused working buffers must not leak into the next call.
  ContactList other = Grid(7, 9);
  ClusterContacts(5, kDefaultClusterNormalScale, &other);
  ContactList second = input;
  ClusterContacts(20, kDefaultClusterNormalScale, &second);
  EXPECT_EQ(first.size(), 20u);
  ExpectIdentical(second, first);
}

// The textbook procedure ClusterContacts follows, written out plainly: farthest-point seeds,
// Lloyd iterations that each label every point afresh, and a final gathering that labels every
// contact again by its nearest final centre. Inputs of at most 250 contacts (no subsample) whose
// clusters never empty; returns false (and nothing) if one does.
using Feature = Eigen::Matrix<double, 7, 1>;

int Nearest(const Feature& f, const std::vector<Feature>& centres) {
  int best = 0;
  for (std::size_t j = 1; j < centres.size(); ++j) {
    if ((f - centres[j]).squaredNorm() < (f - centres[best]).squaredNorm())
      best = static_cast<int>(j);
  }
  return best;
}

bool PlainKMeans(int k, ContactList* contacts) {
  std::vector<Feature> f;
  for (const Contact& c : *contacts) {
    f.push_back(
        (Feature() << c.position, kDefaultClusterNormalScale * c.normal, c.depth).finished());
  }
  std::vector<Feature> centres{f[0]};
  while (static_cast<int>(centres.size()) < k) {
    std::size_t farthest = 0;
    double farthest_distance = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const double d = (f[i] - centres[Nearest(f[i], centres)]).squaredNorm();
      if (d > farthest_distance) farthest_distance = d, farthest = i;
    }
    if (farthest_distance == 0.0) break;
    centres.push_back(f[farthest]);
  }
  std::vector<int> labels(f.size(), -1);
  for (int iteration = 0; iteration < 20; ++iteration) {
    bool changed = false;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const int label = Nearest(f[i], centres);
      changed = changed || label != labels[i];
      labels[i] = label;
    }
    if (!changed) break;
    std::vector<Feature> sums(centres.size(), Feature::Zero());
    std::vector<int> counts(centres.size(), 0);
    for (std::size_t i = 0; i < f.size(); ++i) sums[labels[i]] += f[i], ++counts[labels[i]];
    for (std::size_t j = 0; j < centres.size(); ++j) {
      if (counts[j] == 0) return false;
      centres[j] = sums[j] / static_cast<double>(counts[j]);
    }
  }
  ContactList out;
  for (std::size_t j = 0; j < centres.size(); ++j) {
    Vec3 weighted = Vec3::Zero(), normal_sum = Vec3::Zero();
    double weight = 0.0, depth = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (Nearest(f[i], centres) != static_cast<int>(j)) continue;
      const Contact& c = (*contacts)[i];
      const double w = PressureWeight(c, 1e-9);
      weighted += w * c.position, weight += w, normal_sum += c.normal;
      depth = count == 0 ? c.depth : std::max(depth, c.depth);
      ++count;
    }
    if (count == 0) continue;
    out.push_back(MakeContact(weighted / weight, (normal_sum / count).normalized(), depth));
    out.back().weight = weight;
  }
  *contacts = out;
  return true;
}

TEST(ContactClusteringTest, MatchesThePlainProcedure) {
  // 200 random patches of 25..250 contacts (random positions, normals near +z, depths):
  // ClusterContacts takes its first labels from the seeding and its final ones from a
  // converged iteration, and must still give what labelling afresh every time gives
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    ContactList input;
    const int n = 25 + trial % 226;
    for (int i = 0; i < n; ++i) {
      const Vec3 normal = Vec3(0.3 * u(random), 0.3 * u(random), 1.0).normalized();
      input.push_back(MakeContact(0.1 * Vec3(u(random), u(random), 0.1 * u(random)), normal,
                                  0.01 * (1.0 + u(random))));
    }
    ContactList expected = input;
    if (!PlainKMeans(20, &expected)) continue;
    ++compared;
    ContactList actual = input;
    ClusterContacts(20, kDefaultClusterNormalScale, &actual);
    SCOPED_TRACE(trial);
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
      EXPECT_LT((actual[i].position - expected[i].position).norm(), kMeanTolerance);
      EXPECT_LT((actual[i].normal - expected[i].normal).norm(), kMeanTolerance);
      EXPECT_EQ(actual[i].depth, expected[i].depth);
      EXPECT_NEAR(actual[i].weight, expected[i].weight, kMeanTolerance * expected[i].weight);
    }
  }
  EXPECT_GT(compared, 150);
}

// 3000 contacts of a 300 x 10 strip, 20 clusters: k-means runs on a subsample of
// max(5000 / 20, 44) = 250 contacts. Lamina takes every 12th contact (a uniform stride), so the
// clusters tile the whole strip: 20 cells about 15 cm long whose centroids span all but half a
// cell at each end (~95% of the length). Klamp't's subsample takes index floor(i * 250 / 3000),
// i.e. only the first 21 contacts (the first 20 cm of the strip): its 20 centres cover under 7%
// of the length, and even with every contact assigned to them afterwards, the last cluster
// swallows the rest of the strip (outputs spanning 53%). Seeding from the contacts at indices
// floor(i n / k) fails too: on this row-by-row list the seeds fall on two columns (x = 0 and
// 1.44 m) and Lloyd keeps two bands of 1.5 m (outputs spanning 56%, contacts 0.79 m from the
// nearest output).
TEST(ContactClusteringTest, LargeInputOutputsSpanTheWholeGrid) {
  const ContactList input = Grid(300, 10);
  ContactList contacts = input;
  ClusterContacts(20, kDefaultClusterNormalScale, &contacts);
  ASSERT_EQ(contacts.size(), 20u);
  Eigen::AlignedBox3d input_box;
  Eigen::AlignedBox3d output_box;
  for (const Contact& contact : input) input_box.extend(contact.position);
  for (const Contact& contact : contacts) output_box.extend(contact.position);
  EXPECT_GE(output_box.sizes().x(), 0.9 * input_box.sizes().x());
  EXPECT_TRUE(input_box.contains(output_box));
  // Every input contact is near an output: the cells are about 15 cm x 10 cm (the farthest
  // contact is 11 cm from its output); a cluster that swallowed half the strip would leave
  // contacts 0.7-1.4 m away.
  double farthest = 0.0;
  for (const Contact& contact : input) {
    double nearest = kInf;
    for (const Contact& output : contacts) {
      nearest = std::min(nearest, (output.position - contact.position).norm());
    }
    farthest = std::max(farthest, nearest);
  }
  EXPECT_LE(farthest, 0.12);
}

// Only one contact in twelve enters k-means, but every contact is assigned to the final centres:
// a deep, penetrating contact outside the subsample still sets its cluster's depth and flag.
TEST(ContactClusteringTest, ContactsOutsideTheSubsampleStillCount) {
  ContactList contacts = Grid(300, 10);
  const std::size_t deep = 1501;  // not a multiple of the stride 12
  contacts[deep].depth = 0.05;
  contacts[deep].penetrating = true;
  const Vec3 deep_position = contacts[deep].position;
  ClusterContacts(20, kDefaultClusterNormalScale, &contacts);
  ASSERT_EQ(contacts.size(), 20u);
  int deep_outputs = 0;
  for (const Contact& contact : contacts) {
    if (contact.depth == 0.05) {
      ++deep_outputs;
      EXPECT_TRUE(contact.penetrating);
      // The cluster holding it is local (cells are ~15 cm long).
      EXPECT_LE((contact.position - deep_position).norm(), 0.12);
    } else {
      EXPECT_EQ(contact.depth, 1e-3);
      EXPECT_FALSE(contact.penetrating);
    }
  }
  EXPECT_EQ(deep_outputs, 1);
}

// ---- MergeCoincidentContacts ---------------------------------------------------------------

// The rule as first written (a scan over the survivors): the reference the grid must match.
ContactList MergeReference(double radius, ContactList contacts) {
  constexpr double kSameNormal = 0.9659258262890683;  // cos 15°
  std::size_t kept = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact contact = contacts[i];
    bool merged = false;
    for (std::size_t k = 0; k < kept && !merged; ++k) {
      Contact& survivor = contacts[k];
      if ((survivor.position - contact.position).squaredNorm() > radius * radius) continue;
      if (survivor.normal.dot(contact.normal) < kSameNormal) continue;
      survivor.depth = std::max(survivor.depth, contact.depth);
      survivor.penetrating = survivor.penetrating || contact.penetrating;
      merged = true;
    }
    if (!merged) contacts[kept++] = contact;
  }
  contacts.resize(kept);
  return contacts;
}

// A patch of n contacts on a lattice of spacing `spacing` with jitter, every third one a
// near-duplicate of an earlier one, normals tilted by up to ~25° (some beyond the 15° rule).
ContactList NoisyPatch(int n, double spacing, unsigned seed) {
  unsigned state = seed;
  const auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  };
  ContactList contacts;
  for (int i = 0; i < n; ++i) {
    Vec3 position(spacing * (i % 10) + 0.3 * spacing * uniform(),
                  spacing * (i / 10) + 0.3 * spacing * uniform(), 1e-4 * uniform());
    if (i % 3 == 2) position = contacts[i / 2].position + Vec3::Constant(0.2 * spacing * uniform());
    const Vec3 normal = Vec3(0.45 * (uniform() - 0.5), 0.45 * (uniform() - 0.5), 1.0).normalized();
    contacts.push_back(MakeContact(position, normal, 1e-3 * uniform(), uniform() < 0.1));
  }
  return contacts;
}

// Large inputs take the grid; its result is the scan's, contact for contact, for merge radii
// below, at and above the lattice spacing (cells of every size relative to the patch).
TEST(MergeCoincidentContactsTest, GridMatchesTheScan) {
  for (const double radius : {0.002, 0.01, 0.013, 0.05}) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
      SCOPED_TRACE(testing::Message() << "radius " << radius << " seed " << seed);
      ContactList contacts = NoisyPatch(400, 0.01, seed);
      const ContactList expected = MergeReference(radius, contacts);
      MergeCoincidentContacts(radius, &contacts);
      ExpectIdentical(contacts, expected);
      EXPECT_LT(contacts.size(), 400u);
      EXPECT_GT(contacts.size(), 1u);
    }
  }
}

// Far from the origin, and with a non-finite contact (the scan's rule: NaN merges), the result
// is still the scan's.
TEST(MergeCoincidentContactsTest, FarAndNonFiniteInputsMatchTheScan) {
  ContactList far = NoisyPatch(100, 0.01, 7);
  for (Contact& c : far) c.position += Vec3(1e5, -2e5, 3e4);
  ContactList expected = MergeReference(0.01, far);
  MergeCoincidentContacts(0.01, &far);
  ExpectIdentical(far, expected);

  ContactList broken = NoisyPatch(100, 0.01, 8);
  broken[40].position.x() = std::nan("");
  broken[60].normal = Vec3::Constant(std::nan(""));
  expected = MergeReference(0.01, broken);
  MergeCoincidentContacts(0.01, &broken);
  ASSERT_EQ(broken.size(), expected.size());
  for (std::size_t i = 0; i < broken.size(); ++i) EXPECT_EQ(broken[i].depth, expected[i].depth);
}

// Survivors far apart, each exactly on a corner of the grid's cells so that it enters 8 of them:
// the table holds 8 entries per survivor (it once filled up and looped forever), and nothing
// merges.
TEST(MergeCoincidentContactsTest, SparseSurvivorsOnCellCornersAllStay) {
  const double radius = 0.01;
  ContactList contacts;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 corner(6 * radius * (i % 10), 6 * radius * ((i / 10) % 10), 6 * radius * (i / 100));
    contacts.push_back(MakeContact(corner, Vec3::UnitZ(), 1e-3));
  }
  const ContactList expected = MergeReference(radius, contacts);
  MergeCoincidentContacts(radius, &contacts);
  ExpectIdentical(contacts, expected);
  EXPECT_EQ(contacts.size(), 1000u);
}

// The grid's table is kept between calls and only its used slots emptied: calls of every size,
// one after another, each still give the scan's result.
TEST(MergeCoincidentContactsTest, CallsOfChangingSizesEachMatchTheScan) {
  unsigned seed = 11;
  for (const int n : {1000, 40, 400, 64, 33, 400, 200}) {
    for (const double radius : {0.002, 0.013}) {
      SCOPED_TRACE(testing::Message() << "n " << n << " radius " << radius);
      ContactList contacts = NoisyPatch(n, 0.01, seed++);
      const ContactList expected = MergeReference(radius, contacts);
      MergeCoincidentContacts(radius, &contacts);
      ExpectIdentical(contacts, expected);
    }
  }
}

}  // namespace
}  // namespace lamina::core
