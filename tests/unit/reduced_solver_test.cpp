// SPDX-License-Identifier: MIT
// The solvers' reduced step (core/sim/reduced_basis.h, reduced_system.h, NewtonSolver and
// DirectSolver::SolveReduced): the basis against hand-made velocities, the tree factorization
// against a dense one, and the reduced answers against the bodies' own with stiff joint rows (the
// same law: the joints' rows are what the basis keeps exactly) and against the pendulum's
// symplectic Euler step.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include "core/sim/direct_solver.h"
#include "core/sim/newton_solver.h"
#include "core/sim/reduced_basis.h"
#include "core/sim/reduced_system.h"
#include "tests/common/island_rows.h"

namespace lamina::core {
namespace {

using test::AddContact;
using test::kIslandGravity;

// a 1 m rod of `mass` along x whose centre is `centre`, falling for `step` from `start`
NewtonBody Rod(double mass, const Vec6& start, double step) {
  NewtonBody body;
  body.mass = mass;
  body.inertia = Vec3(1e-4, mass / 12.0, mass / 12.0).asDiagonal();
  body.start = start;
  body.free_velocity = start;
  body.free_velocity(2) -= kIslandGravity * step;
  return body;
}

// the five rows of a hinge with `axis` at `anchor` between body a (centre ca) and b (centre cb, or
// -1: the world), stiff (cfm) and asking for no drift: what the basis keeps exactly
void AddHingeRows(std::vector<NewtonRow>* rows, int a, int b, const Vec3& ca, const Vec3& cb,
                  const Vec3& anchor, const Vec3& axis, double cfm) {
  auto add = [&](const Vec6& ja, const Vec6& jb) {
    NewtonRow row;
    row.a = a;
    row.b = b;
    row.ja = ja;
    row.jb = b >= 0 ? jb : Vec6(Vec6::Zero());
    row.cfm = cfm;
    row.lo = -kInf;
    rows->push_back(row);
  };
  for (const Vec3& e : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY()), Vec3(Vec3::UnitZ())}) {
    Vec6 ja, jb;
    ja << e, (anchor - ca).cross(e);
    jb << -e, -(anchor - cb).cross(e);
    add(ja, jb);
  }
  const Vec3 t1 = axis.unitOrthogonal(), t2 = axis.cross(t1);
  for (const Vec3& t : {t1, t2}) {
    Vec6 ja, jb;
    ja << Vec3::Zero(), t;
    jb << Vec3::Zero(), -t;
    add(ja, jb);
  }
}

TEST(ReducedBasisTest, AHingeTurnsItsBodyAboutItsAxisThroughItsAnchor) {
  ReducedBasis basis;
  std::string why;
  TreeLink hinge{TreeLink::Kind::kHinge, -1, Vec3::UnitY(), Vec3(0.0, 0.0, 2.0)};
  ASSERT_TRUE(basis.Build({Vec3(0.5, 0.0, 2.0)}, {hinge}, &why)) << why;
  ASSERT_EQ(basis.size(), 1);
  VecX u(1);
  u << 3.0;
  const Vec6 v = basis.Velocity(0, u);
  // ω = 3 ŷ, the centre 0.5 m out along x: v = ω × r = 3 ŷ × 0.5 x̂ = −1.5 ẑ
  EXPECT_NEAR((v.head<3>() - Vec3(0.0, 0.0, -1.5)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((v.tail<3>() - Vec3(0.0, 3.0, 0.0)).norm(), 0.0, 1e-15);
}

TEST(ReducedBasisTest, CoordinatesOfTheVelocitiesItMakesAreItsOwn) {
  // a free base, a hinge on it, a slider on that, and a second branch hinged to the base
  std::vector<TreeLink> links(4);
  links[1] = {TreeLink::Kind::kHinge, 0, Vec3(0.0, 0.6, 0.8), Vec3(0.2, 0.0, 0.1)};
  links[2] = {TreeLink::Kind::kSlider, 1, Vec3(1.0, 0.0, 0.0), Vec3::Zero()};
  links[3] = {TreeLink::Kind::kHinge, 0, Vec3::UnitZ(), Vec3(-0.3, 0.1, 0.0)};
  const std::vector<Vec3> centres = {Vec3::Zero(), Vec3(0.5, 0.1, 0.2), Vec3(0.9, -0.2, 0.3),
                                     Vec3(-0.6, 0.4, 0.1)};
  ReducedBasis basis;
  std::string why;
  ASSERT_TRUE(basis.Build(centres, links, &why)) << why;
  ASSERT_EQ(basis.size(), 9);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  VecX u(9);
  for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = unit(random);
  VecX back;
  basis.Coordinates([&](int k) { return basis.Velocity(k, u); }, &back);
  EXPECT_LE((back - u).cwiseAbs().maxCoeff(), 1e-14);
  // the slider's body keeps its parent's rotation; the hinge's anchor point stays on the base's
  // rigid motion
  EXPECT_LE((basis.Velocity(2, u).tail<3>() - basis.Velocity(1, u).tail<3>()).norm(), 1e-15);
  const Vec6 base = basis.Velocity(0, u), child = basis.Velocity(1, u);
  const Vec3 anchor = links[1].anchor;
  const Vec3 on_base = base.head<3>() + base.tail<3>().cross(anchor - centres[0]);
  const Vec3 on_child = child.head<3>() + child.tail<3>().cross(anchor - centres[1]);
  EXPECT_LE((on_base - on_child).norm(), 1e-15);
}

TEST(ReducedBasisTest, ALoopIsRefusedWithItsBody) {
  std::vector<TreeLink> links(2);
  links[0] = {TreeLink::Kind::kHinge, 1, Vec3::UnitZ(), Vec3::Zero()};
  links[1] = {TreeLink::Kind::kHinge, 0, Vec3::UnitZ(), Vec3::Zero()};
  ReducedBasis basis;
  std::string why;
  EXPECT_FALSE(basis.Build({Vec3::Zero(), Vec3::UnitX()}, links, &why));
  EXPECT_NE(why.find("loop"), std::string::npos) << why;
}

// a chain of `count` rods from a world hinge at the origin, laid out along x, each hinged to the
// one before at their shared end (axis y)
struct Chain {
  std::vector<NewtonBody> bodies;
  std::vector<Vec3> centres;
  std::vector<TreeLink> links;
  std::vector<NewtonRow> joint_rows;  ///< the hinges' own rows, for the bodies' solve
};

Chain MakeChain(int count, double step, double cfm, double rate_scale) {
  Chain chain;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  ReducedBasis start_basis;
  for (int k = 0; k < count; ++k) {
    chain.centres.push_back(Vec3(k + 0.5, 0.0, 0.0));
    chain.links.push_back({TreeLink::Kind::kHinge, k - 1, Vec3::UnitY(), Vec3(k, 0.0, 0.0)});
  }
  std::string why;
  EXPECT_TRUE(start_basis.Build(chain.centres, chain.links, &why)) << why;
  VecX rates(count);
  for (int k = 0; k < count; ++k) rates[k] = rate_scale * unit(random);
  for (int k = 0; k < count; ++k) {
    chain.bodies.push_back(Rod(1.0, start_basis.Velocity(k, rates), step));
    const Vec3 cb = k > 0 ? chain.centres[k - 1] : Vec3::Zero();
    AddHingeRows(&chain.joint_rows, k, k - 1, chain.centres[k], cb, Vec3(k, 0.0, 0.0),
                 Vec3::UnitY(), cfm);
  }
  return chain;
}

TEST(ReducedCholeskyTest, TheTreeFactorizationSolvesAsADenseOne) {
  Chain chain = MakeChain(6, 0.01, 1e-9, 1.0);
  // a second branch on the third rod, so the tree is not one path
  chain.centres.push_back(Vec3(2.5, 0.0, -0.5));
  chain.links.push_back({TreeLink::Kind::kHinge, 2, Vec3::UnitX(), Vec3(2.5, 0.0, 0.0)});
  chain.bodies.push_back(Rod(0.5, Vec6::Zero(), 0.01));
  ReducedBasis basis;
  std::string why;
  ASSERT_TRUE(basis.Build(chain.centres, chain.links, &why)) << why;
  std::vector<NewtonRow> rows;
  AddContact(&rows, 6, -1, Vec3(0.0, 0.0, -0.5), Vec3::Zero(), 0.5);  // on one path
  ReducedSystem system;
  system.Build(chain.bodies, rows, basis);
  ASSERT_TRUE(system.on_paths());
  ReducedCholesky tree, dense;
  tree.matrix() = system.mass();
  for (size_t e = system.first(0); e < system.first(1); ++e) {
    for (size_t f = system.first(0); f <= e; ++f) {
      tree.matrix()(system.index()[e], system.index()[f]) +=
          1e3 * system.value()[e] * system.value()[f];
    }
  }
  dense.matrix() = tree.matrix();
  ASSERT_TRUE(tree.Factor(basis, true));
  ASSERT_TRUE(dense.Factor(basis, false));
  VecX b = VecX::LinSpaced(basis.size(), -1.0, 2.0), x_tree = b, x_dense = b;
  tree.Solve(&x_tree);
  dense.Solve(&x_dense);
  EXPECT_LE((x_tree - x_dense).cwiseAbs().maxCoeff(), 1e-12 * x_dense.cwiseAbs().maxCoeff());
  // a contact between the two branches leaves the tree's sparsity
  AddContact(&rows, 6, 4, Vec3(0.0, 0.3, 0.0), Vec3::Zero(), 0.5);
  system.Build(chain.bodies, rows, basis);
  EXPECT_FALSE(system.on_paths());
}

// one step of a rod hung from a world hinge (axis y) at its end, its centre at θ from below the
// anchor towards +x, from rest: gravity's torque about the anchor is +m g d sin θ along y, and the
// reduced step is symplectic Euler in θ: ω_y = h m g d sin θ / I_pivot
TEST(ReducedSolveTest, APendulumTakesTheStepOfItsJointAngle) {
  const double h = 0.001, theta = 1.0, m = 1.0, d = 0.5;
  const Vec3 anchor(0.0, 0.0, 2.0);
  const Vec3 centre = anchor + d * Vec3(std::sin(theta), 0.0, -std::cos(theta));
  const NewtonBody rod = Rod(m, Vec6::Zero(), h);  // (its inertia about y is m / 12 either way)
  ReducedBasis basis;
  std::string why;
  ASSERT_TRUE(basis.Build({centre}, {{TreeLink::Kind::kHinge, -1, Vec3::UnitY(), anchor}}, &why));
  NewtonSolver newton;
  DirectSolver direct;
  NewtonResult by_newton, by_direct;
  ASSERT_TRUE(newton.SolveReduced({rod}, {}, basis, h, {}, &by_newton));
  ASSERT_TRUE(direct.SolveReduced({rod}, {}, basis, h, {}, &by_direct));
  const double pivot_inertia = m / 12.0 + m * d * d;
  const double expected = h * m * kIslandGravity * d * std::sin(theta) / pivot_inertia;
  EXPECT_NEAR(by_newton.velocity[0](4), expected, 1e-12 * std::abs(expected));
  EXPECT_NEAR(by_direct.velocity[0](4), expected, 1e-12 * std::abs(expected));
}

// a 4-rod chain whose tip presses on the ground with friction: the reduced solves (Newton's and
// the direct one) against the bodies' own with the hinges' rows at a stiff cfm
TEST(ReducedSolveTest, AChainOnTheGroundAgreesWithItsBodiesSolvedWithStiffJointRows) {
  const double h = 0.002, cfm = 1e-10;
  Chain chain = MakeChain(4, h, cfm, 0.001);  // (slow: the tip falls onto the ground)
  std::vector<NewtonRow> contacts;
  AddContact(&contacts, 3, -1, Vec3(0.5, 0.0, 0.0), Vec3::Zero(), 0.4);
  std::vector<NewtonRow> all = contacts;
  all.insert(all.end(), chain.joint_rows.begin(), chain.joint_rows.end());
  ReducedBasis basis;
  std::string why;
  ASSERT_TRUE(basis.Build(chain.centres, chain.links, &why)) << why;
  NewtonSolver newton;
  DirectSolver direct;
  NewtonResult reduced_newton, reduced_direct, bodies_newton, bodies_direct;
  ASSERT_TRUE(newton.SolveReduced(chain.bodies, contacts, basis, h, {}, &reduced_newton));
  ASSERT_TRUE(direct.SolveReduced(chain.bodies, contacts, basis, h, {}, &reduced_direct));
  ASSERT_TRUE(newton.Solve(chain.bodies, all, h, {}, &bodies_newton));
  ASSERT_TRUE(direct.Solve(chain.bodies, all, h, {}, &bodies_direct));
  ASSERT_GT(reduced_newton.force[0], 0.1);  // the tip is pressed
  for (size_t k = 0; k < chain.bodies.size(); ++k) {
    EXPECT_LE((reduced_newton.velocity[k] - reduced_direct.velocity[k]).norm(), 1e-10) << k;
    // the stiff rows give way by about cfm · λ / h (λ ~ 10 N): 1e-6 m/s
    EXPECT_LE((reduced_newton.velocity[k] - bodies_newton.velocity[k]).norm(), 2e-6) << k;
    EXPECT_LE((reduced_direct.velocity[k] - bodies_direct.velocity[k]).norm(), 2e-6) << k;
  }
  for (size_t i = 0; i < contacts.size(); ++i) {
    EXPECT_NEAR(reduced_newton.force[i], bodies_newton.force[i],
                1e-4 * std::abs(bodies_newton.force[0]))
        << i;
    EXPECT_NEAR(reduced_direct.force[i], reduced_newton.force[i],
                1e-8 * std::abs(bodies_newton.force[0]))
        << i;
  }
}

// ---- OrientTree -------------------------------------------------------------------------------

TreeEdge HingeEdge(int first, int second) {
  TreeEdge edge;
  edge.first = first;
  edge.second = second;
  edge.link.kind = TreeLink::Kind::kHinge;
  edge.link.axis = Vec3::UnitY();
  edge.link.anchor = Vec3(first, 0, 0);
  return edge;
}

TEST(OrientTreeTest, EdgesGivenChildFirstKeepTheirParents) {
  // a robot's way: 1 and 2 hang from 0, 3 from 2; 0 is free
  const std::vector<TreeEdge> edges = {HingeEdge(3, 2), HingeEdge(1, 0), HingeEdge(2, 0)};
  std::vector<TreeLink> links;
  std::vector<int> child_edge;
  ASSERT_TRUE(OrientTree(4, edges, &links, &child_edge));
  EXPECT_EQ(links[0].kind, TreeLink::Kind::kFree);
  EXPECT_EQ(child_edge[0], -1);
  const int parents[] = {-1, 0, 0, 2}, edge_of[] = {-1, 1, 2, 0};
  for (int k = 1; k < 4; ++k) {
    EXPECT_EQ(links[k].parent, parents[k]) << k;
    EXPECT_EQ(child_edge[k], edge_of[k]) << k;
    EXPECT_EQ(links[k].kind, TreeLink::Kind::kHinge);
    EXPECT_EQ(links[k].anchor, edges[edge_of[k]].link.anchor);
  }
}

TEST(OrientTreeTest, AChainListedAnyWayRoundHangsFromTheWorld) {
  // 0 - 1 - 2 - 3 with 0 on the world, the world's joint last and 0 first in two edges
  const std::vector<TreeEdge> edges = {HingeEdge(0, 1), HingeEdge(2, 1), HingeEdge(2, 3),
                                       HingeEdge(0, -1)};
  std::vector<TreeLink> links;
  std::vector<int> child_edge;
  ASSERT_TRUE(OrientTree(4, edges, &links, &child_edge));
  const int parents[] = {-1, 0, 1, 2}, edge_of[] = {3, 0, 1, 2};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(links[k].kind, TreeLink::Kind::kHinge) << k;
    EXPECT_EQ(links[k].parent, parents[k]) << k;
    EXPECT_EQ(child_edge[k], edge_of[k]) << k;
  }
  ReducedBasis basis;
  std::string why;
  EXPECT_TRUE(basis.Build(std::vector<Vec3>(4, Vec3::Zero()), links, &why)) << why;
  EXPECT_EQ(basis.size(), 4);
}

TEST(OrientTreeTest, TwoPartsWithoutTheWorldGetAFreeRootEach) {
  const std::vector<TreeEdge> edges = {HingeEdge(1, 0), HingeEdge(1, 2), HingeEdge(4, 3),
                                       HingeEdge(4, 5)};
  std::vector<TreeLink> links;
  std::vector<int> child_edge;
  ASSERT_TRUE(OrientTree(6, edges, &links, &child_edge));
  int free = 0;
  for (const TreeLink& link : links) free += link.kind == TreeLink::Kind::kFree;
  EXPECT_EQ(free, 2);
  ReducedBasis basis;
  std::string why;
  EXPECT_TRUE(basis.Build(std::vector<Vec3>(6, Vec3::Zero()), links, &why)) << why;
  EXPECT_EQ(basis.size(), 2 * 6 + 4);
}

TEST(OrientTreeTest, ALoopIsRefused) {
  std::vector<TreeLink> links;
  std::vector<int> child_edge;
  // a ring of three, and a body held by the world twice
  EXPECT_FALSE(
      OrientTree(3, {HingeEdge(0, 1), HingeEdge(0, 2), HingeEdge(1, 2)}, &links, &child_edge));
  EXPECT_FALSE(OrientTree(2, {HingeEdge(0, -1), HingeEdge(0, -1)}, &links, &child_edge));
}

}  // namespace
}  // namespace lamina::core
