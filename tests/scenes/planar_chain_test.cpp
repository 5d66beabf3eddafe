// SPDX-License-Identifier: MIT
// The reference of the linked-pendulum accuracy scenes (core/accuracy/planar_chain.h): its
// equations against the textbook double pendulum of point masses, its RK4 order, its energy, the
// claim that 0.1 ms is fine enough, and reading the scenes' worlds (and refusing other worlds).
#include "core/accuracy/planar_chain.h"

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::PlanarChain;
using core::PlanarChainState;
using core::PlanarChainTrajectory;

Eigen::VectorXd Vector(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (const double value : values) v[i++] = value;
  return v;
}

PlanarChainState State(std::initializer_list<double> angle, std::initializer_list<double> rate) {
  return {Vector(angle), Vector(rate)};
}

// The double pendulum of two point masses (myphysicslab's closed form, angles from down).
Eigen::Vector2d TextbookAccelerations(double m1, double m2, double l1, double l2, double g,
                                      const PlanarChainState& s) {
  const double t1 = s.angle[0], t2 = s.angle[1], w1 = s.rate[0], w2 = s.rate[1];
  const double den = 2 * m1 + m2 - m2 * std::cos(2 * t1 - 2 * t2);
  const double a1 =
      (-g * (2 * m1 + m2) * std::sin(t1) - m2 * g * std::sin(t1 - 2 * t2) -
       2 * std::sin(t1 - t2) * m2 * (w2 * w2 * l2 + w1 * w1 * l1 * std::cos(t1 - t2))) /
      (l1 * den);
  const double a2 = 2 * std::sin(t1 - t2) *
                    (w1 * w1 * l1 * (m1 + m2) + g * (m1 + m2) * std::cos(t1) +
                     w2 * w2 * l2 * m2 * std::cos(t1 - t2)) /
                    (l2 * den);
  return {a1, a2};
}

TEST(PlanarChain, PointMassesMatchTheTextbookDoublePendulum) {
  const PlanarChain chain{{{1.3, 0.0, 0.7, 0.7}, {0.6, 0.0, 1.1, 0.0}}, 9.81};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-5.0, 5.0);
  for (int i = 0; i < 100; ++i) {
    const PlanarChainState s = State({angle(random), angle(random)}, {rate(random), rate(random)});
    const Eigen::Vector2d expected = TextbookAccelerations(1.3, 0.6, 0.7, 1.1, 9.81, s);
    EXPECT_NEAR((chain.Accelerations(s) - expected).norm(), 0.0, 1e-11 * (1 + expected.norm()));
  }
}

TEST(PlanarChain, OneRodIsThePhysicalPendulum) {
  // I_pivot·θ̈ = −m·g·c·sin θ
  const PlanarChain chain{{{2.0, 0.05, 0.4, 1.0}}, 9.8};
  const PlanarChainState s = State({0.8}, {1.5});
  const double pivot_inertia = 0.05 + 2.0 * 0.4 * 0.4;
  EXPECT_NEAR(chain.Accelerations(s)[0], -2.0 * 9.8 * 0.4 * std::sin(0.8) / pivot_inertia, 1e-13);
  EXPECT_NEAR(chain.Energy(s), 0.5 * pivot_inertia * 1.5 * 1.5 - 2.0 * 9.8 * 0.4 * std::cos(0.8),
              1e-13);
}

// Ten 0.2 m rods released level, the chain_10 scene's chain.
PlanarChain TenRods() {
  PlanarChain chain;
  for (int k = 0; k < 10; ++k) chain.links.push_back({0.2, 6.7333333333333e-4, 0.1, 0.2});
  return chain;
}

PlanarChainState Level(int links) {
  PlanarChainState s;
  s.angle = Eigen::VectorXd::Constant(links, std::numbers::pi / 2);
  s.rate = Eigen::VectorXd::Zero(links);
  return s;
}

double TipDistance(const PlanarChain& chain, const PlanarChainState& a, const PlanarChainState& b) {
  return (chain.Centres(a.angle).back() - chain.Centres(b.angle).back()).norm();
}

TEST(PlanarChain, Rk4IsFourthOrder) {
  const PlanarChain chain = TenRods();
  const double duration = 0.5;
  const PlanarChainTrajectory fine(chain, Level(10), duration, 2.5e-5);
  const PlanarChainTrajectory mid(chain, Level(10), duration, 1e-3);
  const PlanarChainTrajectory coarse(chain, Level(10), duration, 2e-3);
  const double e_mid = TipDistance(chain, mid.State(duration), fine.State(duration));
  const double e_coarse = TipDistance(chain, coarse.State(duration), fine.State(duration));
  EXPECT_NEAR(std::log2(e_coarse / e_mid), 4.0, 0.3) << e_coarse << " " << e_mid;
}

TEST(PlanarChain, TheSceneStepIsFineEnoughAndKeepsEnergy) {
  // the scenes compare Lamina with the reference at 0.1 ms: halving it moves no centre by 1e-9 m
  for (const int links : {2, 10}) {
    const PlanarChain chain =
        links == 2 ? PlanarChain{{{1, 0.0833667, 0.5, 1}, {1, 0.0833667, 0.5, 1}}, 9.8} : TenRods();
    const double duration = links == 2 ? 1.5 : 1.0;
    const PlanarChainTrajectory used(chain, Level(links), duration, 1e-4);
    const PlanarChainTrajectory half(chain, Level(links), duration, 5e-5);
    for (double t = 0.0; t <= duration; t += 0.0137) {
      const auto a = chain.Centres(used.State(t).angle), b = chain.Centres(half.State(t).angle);
      for (std::size_t k = 0; k < a.size(); ++k) EXPECT_LT((a[k] - b[k]).norm(), 1e-9) << t;
      EXPECT_NEAR(chain.Energy(used.State(t)), chain.Energy(Level(links)), 1e-8) << t;
    }
  }
}

TEST(PlanarChain, InterpolationBetweenSamplesIsFourthOrderToo) {
  const PlanarChain chain = TenRods();
  const PlanarChainTrajectory coarse(chain, Level(10), 0.4, 1e-4);
  const PlanarChainTrajectory fine(chain, Level(10), 0.4, 1e-5);
  for (double t = 0.00003; t < 0.4; t += 0.01234) {
    EXPECT_LT((coarse.State(t).angle - fine.State(t).angle).norm(), 1e-9) << t;
    EXPECT_LT((coarse.State(t).rate - fine.State(t).rate).norm(), 1e-7) << t;
  }
}

core::WorldDesc AccuracyWorld(const std::string& file) {
  return test::LoadShippedWorld("accuracy/" + file);
}

TEST(PlanarChain, ReadsTheDoublePendulumWorld) {
  const core::WorldDesc world = AccuracyWorld("double_pendulum.xml");
  core::WorldPlanarChain read;
  ASSERT_EQ(core::ReadPlanarChain(world, &read), "");
  ASSERT_EQ(read.chain.links.size(), 2u);
  for (const core::PlanarLink& link : read.chain.links) {
    EXPECT_NEAR(link.mass, 1.0, 1e-15);
    EXPECT_NEAR(link.com, 0.5, 1e-12);
    EXPECT_NEAR(link.inertia, (1.0 + 0.0004) / 12.0, 1e-12);
  }
  EXPECT_NEAR(read.chain.links[0].length, 1.0, 1e-12);
  EXPECT_NEAR(read.start.angle[0], std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(read.start.angle[1], std::numbers::pi / 2, 1e-12);
  const std::vector<core::Vec3> centres = read.Centres(read.start.angle);
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const core::Vec3 com = world.objects[k].pose * world.objects[k].com;
    EXPECT_LT((centres[k] - com).norm(), 1e-12) << k;
  }
}

TEST(PlanarChain, RefusesWhatIsNotAPlanarChain) {
  core::WorldDesc world = AccuracyWorld("chain_10.xml");
  core::WorldPlanarChain read;
  ASSERT_EQ(core::ReadPlanarChain(world, &read), "");
  EXPECT_EQ(read.chain.links.size(), 10u);
  core::WorldDesc tilted = world;
  tilted.joints[3].axis = core::Vec3(0, 0.1, 1).normalized();
  EXPECT_EQ(core::ReadPlanarChain(tilted, &read), "joint 3's axis is not parallel to joint 0's");
  core::WorldDesc slider = world;
  slider.joints[1].type = core::WorldJointType::kSlider;
  EXPECT_EQ(core::ReadPlanarChain(slider, &read), "joint 1 is not a hinge");
  core::WorldDesc bent = world;
  bent.objects[4].com.x() += 0.01;
  EXPECT_EQ(core::ReadPlanarChain(bent, &read),
            "object 4's centre of mass is off the line of its hinges");
  core::WorldDesc pendulum = AccuracyWorld("pendulum.xml");
  EXPECT_EQ(core::ReadPlanarChain(pendulum, &read), "");
}

}  // namespace
}  // namespace lamina
