// SPDX-License-Identifier: MIT
// The parameter table (core/model/params.h) on its own: the rows are well formed, every row's
// get/set and text round trip, and CheckParam draws each line where the table says (exclusive
// minimum, inclusive maximum, inf where allowed, NaN, sizes, ranges, rotations, inertias,
// integers, choices). The files and the simulator against the table: tests/io/params_io_test.cpp.
#include "core/model/params.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/model/element.h"
#include "core/model/surface_rows.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::ElementIndex;
using core::ElementKind;
using core::ParamSpec;
using core::ParamType;
using core::ParamValue;

using core::kInf;
constexpr ElementKind kKinds[] = {ElementKind::kSettings, ElementKind::kTerrain,
                                  ElementKind::kObject,   ElementKind::kRobot,
                                  ElementKind::kLink,     ElementKind::kDriver};

const ParamSpec& Row(std::string_view key, ElementKind kind) {
  const ParamSpec* spec = core::FindParam(key, kind);
  EXPECT_NE(spec, nullptr) << key;
  return *spec;
}

bool Accepts(std::string_view key, ElementKind kind, const ParamValue& value) {
  return core::ParamAccepts(Row(key, kind), value, static_cast<int>(value.size()));
}

bool SameBits(const ParamValue& a, const ParamValue& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

// a world with one element of each kind (tests/data/params/fixture.xml, loaded once)
const core::WorldDesc& Fixture() {
  static const core::WorldDesc world = [] {
    test::LoadedWorld loaded;
    test::LoadWorld(test::DataPath("params/fixture.xml"), &loaded);
    EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
    return loaded.world;
  }();
  return world;
}

// the first element of each kind in the fixture
ElementIndex FirstOf(ElementKind kind) {
  switch (kind) {
    case ElementKind::kSettings:
      return ElementIndex::Settings();
    case ElementKind::kTerrain:
      return ElementIndex::Terrain(0);
    case ElementKind::kObject:
      return ElementIndex::Object(0);
    case ElementKind::kRobot:
      return ElementIndex::Robot(0);
    case ElementKind::kLink:
      return ElementIndex::Link(0, 1);
    case ElementKind::kDriver:
      return ElementIndex::Driver(0, 0);
  }
  return {};
}

// ---- the rows ---------------------------------------------------------------------------------

TEST(ParamTableTest, KeysAreUniquePerElementKind) {
  for (ElementKind kind : kKinds) {
    std::set<std::string_view> keys;
    for (const ParamSpec* spec : core::ParamsOf(kind)) {
      EXPECT_TRUE(keys.insert(spec->key).second) << spec->key;
      EXPECT_EQ(core::FindParam(spec->key, kind), spec) << spec->key;
    }
  }
  EXPECT_NE(core::FindParam("velocity", ElementKind::kObject),
            core::FindParam("velocity", ElementKind::kRobot));
}

TEST(ParamTableTest, EveryRowHasLabelHelpKindsAndASaneRange) {
  for (const ParamSpec& spec : core::Params()) {
    EXPECT_FALSE(spec.label.empty()) << spec.key;
    EXPECT_FALSE(spec.help.empty()) << spec.key;
    EXPECT_NE(spec.kinds, 0u) << spec.key;
    EXPECT_LE(spec.min, spec.max) << spec.key;
    EXPECT_FALSE(std::isinf(spec.min) && spec.min > 0) << spec.key;
    EXPECT_FALSE(std::isinf(spec.max) && spec.max < 0) << spec.key;
    EXPECT_TRUE(spec.get != nullptr && spec.set != nullptr) << spec.key;
    EXPECT_EQ(core::ParamId(spec), &spec - core::Params().data()) << spec.key;
    if (spec.type == ParamType::kChoice) {
      EXPECT_EQ(spec.min, 0.0) << spec.key;
      EXPECT_EQ(spec.max, static_cast<double>(spec.choices.size()) - 1.0) << spec.key;
    } else {
      EXPECT_TRUE(spec.choices.empty()) << spec.key;
    }
    if (spec.type == ParamType::kBool) {
      EXPECT_TRUE(spec.min == 0.0 && spec.max == 1.0) << spec.key;
    }
  }
}

TEST(ParamTableTest, EveryRowBelongsToTheElementsItNames) {
  // every kind has rows, and every row is found under each kind it names
  for (ElementKind kind : kKinds) EXPECT_FALSE(core::ParamsOf(kind).empty());
  for (const ParamSpec& spec : core::Params()) {
    for (ElementKind kind : kKinds) {
      if (!spec.AppliesTo(kind)) continue;
      EXPECT_EQ(core::FindParam(spec.key, kind), &spec) << spec.key;
      EXPECT_TRUE(core::GetParam(Fixture(), FirstOf(kind), spec).has_value()) << spec.key;
    }
  }
}

// ---- get/set and text round trips ----------------------------------------------------------

// A valid value of `spec` other than `current` (every component changed where the type allows).
ParamValue OtherValue(const ParamSpec& spec, const ParamValue& current) {
  switch (spec.type) {
    case ParamType::kBool:
      return {1.0 - current[0]};
    case ParamType::kChoice:
      return {std::fmod(current[0] + 1.0, static_cast<double>(spec.choices.size()))};
    case ParamType::kInteger:
      return {current[0] + 1.0};
    case ParamType::kRange:
      return {current[0] - 0.5, std::isinf(current[1]) ? 3.5 : current[1] + 0.5};
    case ParamType::kPose: {
      core::Pose pose = core::Pose::Identity();
      pose.linear() = Eigen::AngleAxisd(0.7, core::Vec3::UnitY()).toRotationMatrix();
      pose.translation() = core::Vec3(1, 2, 3);
      return core::PoseToValue(pose);
    }
    case ParamType::kInertia:
      return {0.5, 0.1, 0, 0.1, 0.4, 0, 0, 0, 0.3};
    default: {
      ParamValue value = current;
      for (double& x : value) {
        x = std::isfinite(spec.max) ? 0.5 * (spec.min + spec.max) + 0.01 * x
                                    : (std::isfinite(x) ? 2.0 * x + 0.25 : 4.0);
      }
      return value;
    }
  }
}

TEST(ParamTableTest, GetSetRoundTripsForEveryRow) {
  for (const ParamSpec& spec : core::Params()) {
    for (ElementKind kind : kKinds) {
      if (!spec.AppliesTo(kind)) continue;
      core::WorldDesc world = Fixture();
      const ElementIndex element = FirstOf(kind);
      const ParamValue before = *core::GetParam(world, element, spec);
      const ParamValue value = OtherValue(spec, before);
      ASSERT_FALSE(SameBits(value, before)) << spec.key;
      std::string error;
      ASSERT_TRUE(core::SetParam(&world, element, spec, value, &error)) << error;
      EXPECT_TRUE(SameBits(*core::GetParam(world, element, spec), value)) << spec.key;
    }
  }
}

TEST(ParamTableTest, TextRoundTripsForEveryRow) {
  for (const ParamSpec& spec : core::Params()) {
    for (ElementKind kind : kKinds) {
      if (!spec.AppliesTo(kind)) continue;
      const ParamValue current = *core::GetParam(Fixture(), FirstOf(kind), spec);
      for (const ParamValue& value : {current, OtherValue(spec, current)}) {
        const std::string text = core::FormatParamValue(spec, value);
        std::string error;
        const auto parsed = core::ParseParamValue(spec, text, &error);
        ASSERT_TRUE(parsed.has_value()) << spec.key << " '" << text << "': " << error;
        EXPECT_TRUE(SameBits(*parsed, value)) << spec.key << " '" << text << "'";
      }
    }
  }
}

TEST(ParamTableTest, TextNamesBoolsChoicesAndInfinities) {
  std::string error;
  const ParamSpec& solver = Row("solver", ElementKind::kSettings);
  EXPECT_EQ(core::FormatParamValue(solver, {1}), "quick");
  EXPECT_EQ(*core::ParseParamValue(solver, "quick", &error), ParamValue{1});
  EXPECT_EQ(core::FormatParamValue(Row("sleeping", ElementKind::kSettings), {1}), "true");
  EXPECT_EQ(core::FormatParamValue(Row("jointLimits", ElementKind::kLink), {-kInf, 2.5}),
            "-inf,2.5");
  const ParamSpec& inertia = Row("inertia", ElementKind::kObject);
  EXPECT_EQ(*core::ParseParamValue(inertia, "1,2,3", &error),
            (ParamValue{1, 0, 0, 0, 2, 0, 0, 0, 3}));
  EXPECT_FALSE(core::ParseParamValue(Row("kFriction", ElementKind::kObject), "0.5x", &error));
  EXPECT_EQ(error, "'0.5x' is not a value of kFriction, which must be >= 0 (inf allowed)");
}

// Lamina's rolling and spinning friction: one row each for every body, next to kFriction, in m,
// finite and >= 0, live, and left out of saved files while off (not Klamp't's)
TEST(ParamTableTest, RollingAndSpinningFrictionAreBodySurfaceRows) {
  for (std::string_view key : {"kRollingFriction", "kSpinningFriction"}) {
    for (ElementKind kind : {ElementKind::kTerrain, ElementKind::kObject, ElementKind::kLink}) {
      const ParamSpec& spec = Row(key, kind);
      EXPECT_EQ(spec.unit, "m");
      EXPECT_EQ(spec.type, ParamType::kReal);
      EXPECT_EQ(spec.apply, core::ParamApply::kLive);
      EXPECT_FALSE(spec.klampt);
      EXPECT_TRUE(core::IsBodyParam(spec));
      EXPECT_EQ(core::ParamRule(spec), "must be >= 0");
      EXPECT_TRUE(Accepts(key, kind, {0.0}));
      EXPECT_TRUE(Accepts(key, kind, {0.005}));
      EXPECT_FALSE(Accepts(key, kind, {std::nextafter(0.0, -1.0)}));
      EXPECT_FALSE(Accepts(key, kind, {kInf}));
    }
    EXPECT_EQ(core::FindParam(key, ElementKind::kRobot), nullptr);
    EXPECT_EQ(core::FindParam(key, ElementKind::kSettings), nullptr);
  }
  // in table order right after kFriction, and among the surface rows every consumer lists
  const ParamSpec& friction = Row("kFriction", ElementKind::kObject);
  EXPECT_EQ(&Row("kRollingFriction", ElementKind::kObject), &friction + 1);
  EXPECT_EQ(&Row("kSpinningFriction", ElementKind::kObject), &friction + 2);
  std::vector<std::string_view> surface;
  for (const core::SurfaceRow& row : core::SurfaceMembers()) surface.push_back(row.spec->key);
  EXPECT_THAT(surface, ::testing::ElementsAre("kRestitution", "kFriction", "kRollingFriction",
                                              "kSpinningFriction", "kStiffness", "kDamping"));
  // get and set reach the SurfaceDesc fields of terrains, objects and links
  core::WorldDesc world = Fixture();
  std::string error;
  ASSERT_TRUE(core::SetParam(&world, ElementIndex::Link(0, 1),
                             Row("kRollingFriction", ElementKind::kLink), {0.003}, &error));
  EXPECT_EQ(world.robots[0].links[1].sim.surface.rolling_friction, 0.003);
  ASSERT_TRUE(core::SetParam(&world, ElementIndex::Terrain(0),
                             Row("kSpinningFriction", ElementKind::kTerrain), {0.002}, &error));
  EXPECT_EQ(world.terrains[0].sim.surface.spinning_friction, 0.002);
  EXPECT_FALSE(core::SetParam(&world, ElementIndex::Object(1),
                              Row("kRollingFriction", ElementKind::kObject), {-0.01}, &error));
  EXPECT_EQ(error, "objects[1].kRollingFriction must be >= 0, got -0.01");
  EXPECT_EQ(*core::GetParam(world, ElementIndex::Object(1),
                            Row("kRollingFriction", ElementKind::kObject)),
            ParamValue{0.0});
}

// ---- CheckParam at the boundaries --------------------------------------------------------------

TEST(ParamCheckTest, ExclusiveMinimumRefusesTheBoundItself) {
  EXPECT_FALSE(Accepts("timestep", ElementKind::kSettings, {0.0}));
  EXPECT_TRUE(Accepts("timestep", ElementKind::kSettings, {std::nextafter(0.0, 1.0)}));
  EXPECT_FALSE(Accepts("kStiffness", ElementKind::kObject, {0.0}));
  EXPECT_TRUE(Accepts("kStiffness", ElementKind::kObject, {1e-300}));
}

TEST(ParamCheckTest, InclusiveBoundsAcceptTheBoundAndNothingBeyond) {
  EXPECT_TRUE(Accepts("kRestitution", ElementKind::kObject, {1.0}));
  EXPECT_FALSE(Accepts("kRestitution", ElementKind::kObject, {std::nextafter(1.0, 2.0)}));
  EXPECT_TRUE(Accepts("kRestitution", ElementKind::kTerrain, {0.0}));
  EXPECT_FALSE(Accepts("kRestitution", ElementKind::kTerrain, {-0.001}));
  EXPECT_TRUE(Accepts("kFriction", ElementKind::kLink, {0.0}));
  EXPECT_FALSE(Accepts("kFriction", ElementKind::kLink, {std::nextafter(0.0, -1.0)}));
  EXPECT_TRUE(Accepts("ERP", ElementKind::kSettings, {1.0}));
  EXPECT_FALSE(Accepts("ERP", ElementKind::kSettings, {1.0000001}));
}

TEST(ParamCheckTest, InfinityOnlyWhereTheRowAllowsIt) {
  EXPECT_TRUE(Accepts("kStiffness", ElementKind::kObject, {kInf}));
  EXPECT_TRUE(Accepts("kDamping", ElementKind::kObject, {kInf}));
  EXPECT_TRUE(Accepts("kFriction", ElementKind::kObject, {kInf}));
  EXPECT_FALSE(Accepts("kStiffness", ElementKind::kObject, {-kInf}));
  EXPECT_FALSE(Accepts("kRestitution", ElementKind::kObject, {kInf}));
  EXPECT_FALSE(Accepts("timestep", ElementKind::kSettings, {kInf}));
  EXPECT_FALSE(Accepts("mass", ElementKind::kObject, {kInf}));
  EXPECT_FALSE(Accepts("servoP", ElementKind::kDriver, {kInf}));
  EXPECT_FALSE(Accepts("gravity", ElementKind::kSettings, {0, 0, -kInf}));
  // ranges: either end may be infinite, with either sign
  EXPECT_TRUE(Accepts("jointLimits", ElementKind::kLink, {-kInf, kInf}));
  EXPECT_TRUE(Accepts("torqueLimits", ElementKind::kDriver, {-kInf, 3}));
  EXPECT_FALSE(Accepts("config", ElementKind::kRobot, {0, kInf, 0}));
}

TEST(ParamCheckTest, NaNIsRefusedByEveryRow) {
  for (const ParamSpec& spec : core::Params()) {
    const int size = spec.type == ParamType::kVector ? 3 : core::ParamSize(spec, {}, {});
    ParamValue value(static_cast<size_t>(size), 0.0);
    value.back() = std::nan("");
    EXPECT_FALSE(core::ParamAccepts(spec, value, size)) << spec.key;
  }
}

TEST(ParamCheckTest, EveryRowRefusesTheWrongSize) {
  for (const ParamSpec& spec : core::Params()) {
    for (ElementKind kind : kKinds) {
      if (!spec.AppliesTo(kind)) continue;
      const ElementIndex element = FirstOf(kind);
      const int size = core::ParamSize(spec, Fixture(), element);
      ParamValue value = *core::GetParam(Fixture(), element, spec);
      ASSERT_TRUE(core::ParamAccepts(spec, value, size)) << spec.key;
      value.push_back(value.back());
      EXPECT_FALSE(core::ParamAccepts(spec, value, size)) << spec.key;
      value.resize(value.size() - 2);
      EXPECT_FALSE(core::ParamAccepts(spec, value, size)) << spec.key;
    }
  }
}

TEST(ParamCheckTest, RangesMustBeOrdered) {
  EXPECT_FALSE(Accepts("jointLimits", ElementKind::kLink, {1.0, 0.0}));
  EXPECT_TRUE(Accepts("jointLimits", ElementKind::kLink, {0.5, 0.5}));
  EXPECT_FALSE(Accepts("velocityLimits", ElementKind::kDriver, {kInf, -kInf}));
  EXPECT_EQ(*core::CheckParam(Row("jointLimits", ElementKind::kLink), {1, 0}, 2),
            "jointLimits must be 2 numbers min <= max (inf and -inf allowed), got 1,0");
}

TEST(ParamCheckTest, PosesMustBeRigid) {
  const ParamSpec& transform = Row("transform", ElementKind::kObject);
  core::Pose pose = core::Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(1.0, core::Vec3(1, 1, 0).normalized()).toRotationMatrix();
  EXPECT_TRUE(core::ParamAccepts(transform, core::PoseToValue(pose), 12));
  core::Pose scaled = pose;
  scaled.linear() *= 1.01;
  EXPECT_FALSE(core::ParamAccepts(transform, core::PoseToValue(scaled), 12));
  core::Pose mirrored = pose;
  mirrored.linear().col(0) *= -1.0;  // orthonormal, determinant -1
  EXPECT_FALSE(core::ParamAccepts(transform, core::PoseToValue(mirrored), 12));
  ParamValue far = core::PoseToValue(pose);
  far[11] = kInf;
  EXPECT_FALSE(core::ParamAccepts(transform, far, 12));
}

TEST(ParamCheckTest, InertiasMustBeSymmetricPositiveSemiDefinite) {
  EXPECT_TRUE(Accepts("inertia", ElementKind::kLink, {1, 0.5, 0, 0.5, 1, 0, 0, 0, 1}));
  EXPECT_TRUE(Accepts("inertia", ElementKind::kLink, {0, 0, 0, 0, 0, 0, 0, 0, 0}));
  EXPECT_FALSE(Accepts("inertia", ElementKind::kLink, {1, 0.5, 0, 0, 1, 0, 0, 0, 1}));
  // symmetric with a negative eigenvalue: 1 - 2 = -1 along (1, -1, 0)
  EXPECT_FALSE(Accepts("inertia", ElementKind::kObject, {1, 2, 0, 2, 1, 0, 0, 0, 1}));
  EXPECT_FALSE(Accepts("inertia", ElementKind::kObject, {1, 0, 0, 0, -1e-6, 0, 0, 0, 1}));
}

TEST(ParamCheckTest, IntegersMustBeWholeAndInRange) {
  EXPECT_TRUE(Accepts("maxContacts", ElementKind::kSettings, {1}));
  EXPECT_TRUE(Accepts("maxContacts", ElementKind::kSettings, {1e6}));
  EXPECT_FALSE(Accepts("maxContacts", ElementKind::kSettings, {0}));
  EXPECT_FALSE(Accepts("maxContacts", ElementKind::kSettings, {1e6 + 1}));
  EXPECT_FALSE(Accepts("maxContacts", ElementKind::kSettings, {2.5}));
  EXPECT_FALSE(Accepts("quickStepIterations", ElementKind::kSettings, {kInf}));
}

TEST(ParamCheckTest, ChoicesAndBoolsMustBeInRange) {
  EXPECT_TRUE(Accepts("preshrink", ElementKind::kObject, {2}));
  EXPECT_FALSE(Accepts("preshrink", ElementKind::kObject, {3}));
  EXPECT_FALSE(Accepts("preshrink", ElementKind::kObject, {-1}));
  EXPECT_FALSE(Accepts("preshrink", ElementKind::kObject, {1.5}));
  EXPECT_TRUE(Accepts("solver", ElementKind::kSettings, {2}));
  EXPECT_FALSE(Accepts("solver", ElementKind::kSettings, {3}));
  EXPECT_TRUE(Accepts("sleeping", ElementKind::kSettings, {1}));
  EXPECT_FALSE(Accepts("sleeping", ElementKind::kSettings, {0.5}));
  EXPECT_FALSE(Accepts("sleeping", ElementKind::kSettings, {2}));
}

TEST(ParamCheckTest, MessagesStateTheRuleAndTheValue) {
  EXPECT_EQ(*core::CheckParam(Row("kRestitution", ElementKind::kObject), {1.5}, 1),
            "kRestitution must be in [0, 1], got 1.5");
  EXPECT_EQ(*core::CheckParam(Row("kStiffness", ElementKind::kObject), {0}, 1),
            "kStiffness must be > 0 (inf allowed), got 0");
  EXPECT_EQ(*core::CheckParam(Row("gravity", ElementKind::kSettings), {0, 0}, 3),
            "gravity must be 3 finite numbers, got 0,0 (2 numbers, needs 3)");
  EXPECT_EQ(core::CheckParam(Row("kRestitution", ElementKind::kObject), {0.5}, 1), std::nullopt);
  std::string error;
  core::WorldDesc world = Fixture();
  EXPECT_FALSE(core::SetParam(&world, ElementIndex::Object(1),
                              Row("kRestitution", ElementKind::kObject), {1.5}, &error));
  EXPECT_EQ(error, "objects[1].kRestitution must be in [0, 1], got 1.5");
}

}  // namespace
}  // namespace lamina
