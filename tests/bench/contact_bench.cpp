// SPDX-License-Identifier: MIT
// The contact pipeline of one pair, piece by piece, on stiffness_test.xml's case: its 960-triangle
// ball (radius 0.1 m, 4 cm of padding) resting 3 cm deep in its layer on the 4 m slab, as the
// simulator meets it every step. Contacts: the mesh-mesh contacts with kept triangle pairs (the
// ball still, so every call after the first reuses them); Merge: folding coincident contacts;
// Cluster: k-means down to the world's 20. Each checks its answer once before timing.
#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include <benchmark/benchmark.h>

#include "core/contact/collision_geometry.h"
#include "core/contact/contact_clustering.h"
#include "core/contact/mesh_contacts.h"
#include "core/contact/near_pair_cache.h"
#include "core/io/mesh_file.h"
#include "core/math_types.h"
#include "core/sim/contact_set.h"

namespace lamina::bench {
namespace {

constexpr double kPadding = 0.04;  // each side, as the ball's padding with the slab's margin
constexpr double kSunk = 0.03;     // of the 8 cm layer
constexpr int kMaxContacts = 20;
// as FindPairContacts merges them (contact_set.h)
constexpr double kMergeRadius =
    std::max(core::kMergeFraction * 2 * kPadding, core::kMinimumMergeRadius);

std::shared_ptr<const core::CollisionGeometry> Mesh(const std::string& relative, double scale) {
  core::Diagnostics diagnostics;
  std::optional<core::TriangleMesh> mesh =
      core::ReadMeshFile(std::string(LAMINA_WORLDS_DIR) + "/" + relative, {}, diagnostics);
  if (!mesh) return nullptr;
  core::GeometryDesc desc;
  desc.kind = core::GeometryKind::kMesh;
  desc.mesh = std::make_shared<const core::TriangleMesh>(std::move(*mesh));
  desc.scale = core::Vec3::Constant(scale);
  return core::CollisionGeometry::Build(desc);
}

struct BallOnSlab {
  std::shared_ptr<const core::CollisionGeometry> ball = Mesh("klampt/objects/sphere.off", 0.1);
  std::shared_ptr<const core::CollisionGeometry> slab = Mesh("klampt/terrains/block.off", 1.0);
  core::Pose ball_pose = core::Pose::Identity();
  core::NearPairCache cache;

  BallOnSlab() {
    ball_pose.linear() = core::RotationFromRollPitchYaw(0.3, -0.2, 0.7);
    ball_pose.translation() = core::Vec3(0.1, -0.2, 0.1 + 2 * kPadding - kSunk);
  }
  bool Loaded() const { return ball != nullptr && slab != nullptr; }
  void Contacts(core::ContactList* out) {
    out->clear();
    core::MeshMeshContacts(*ball, ball_pose, kPadding, *slab, core::Pose::Identity(), kPadding, out,
                           &cache);
  }
  core::ContactList Merged() {
    core::ContactList contacts;
    Contacts(&contacts);
    core::MergeCoincidentContacts(kMergeRadius, &contacts);
    return contacts;
  }
};

void BM_BallOnSlabContacts(benchmark::State& state) {
  BallOnSlab scene;
  if (!scene.Loaded()) return state.SkipWithError("cannot read the ball or the slab");
  core::ContactList contacts;
  scene.Contacts(&contacts);
  if (contacts.size() < 100) return state.SkipWithError("too few contacts");
  for (auto _ : state) {
    scene.Contacts(&contacts);
    benchmark::DoNotOptimize(contacts.data());
  }
  state.counters["contacts"] = static_cast<double>(contacts.size());
}
BENCHMARK(BM_BallOnSlabContacts)
    ->Name("Contacts/ball_on_slab/mesh_mesh")
    ->Unit(benchmark::kMicrosecond);

void BM_BallOnSlabMerge(benchmark::State& state) {
  BallOnSlab scene;
  if (!scene.Loaded()) return state.SkipWithError("cannot read the ball or the slab");
  core::ContactList raw;
  scene.Contacts(&raw);
  core::ContactList contacts;
  for (auto _ : state) {
    contacts = raw;
    core::MergeCoincidentContacts(kMergeRadius, &contacts);
    benchmark::DoNotOptimize(contacts.data());
  }
  state.counters["in"] = static_cast<double>(raw.size());
  state.counters["out"] = static_cast<double>(contacts.size());
}
BENCHMARK(BM_BallOnSlabMerge)->Name("Contacts/ball_on_slab/merge")->Unit(benchmark::kMicrosecond);

void BM_BallOnSlabCluster(benchmark::State& state) {
  BallOnSlab scene;
  if (!scene.Loaded()) return state.SkipWithError("cannot read the ball or the slab");
  const core::ContactList merged = scene.Merged();
  core::ContactList contacts;
  for (auto _ : state) {
    contacts = merged;
    core::ClusterContacts(kMaxContacts, core::kDefaultClusterNormalScale, &contacts);
    benchmark::DoNotOptimize(contacts.data());
  }
  if (contacts.size() != kMaxContacts) return state.SkipWithError("not reduced to 20 contacts");
  state.counters["in"] = static_cast<double>(merged.size());
}
BENCHMARK(BM_BallOnSlabCluster)
    ->Name("Contacts/ball_on_slab/cluster")
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace lamina::bench
