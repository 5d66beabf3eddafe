// SPDX-License-Identifier: MIT
// Access paths on a WorldDesc: the syntax (quoted names, bad syntax with its column), every kind
// of row read and written, components, Klamp't's aliases, and every error message.
#include "core/model/access_path.h"

#include <initializer_list>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/model/world_compare.h"
#include "tests/common/scene_builders.h"

namespace lamina {
namespace {

using core::AccessContext;
using core::ParamValue;
using core::Vec3;

// a terrain, three objects ("block" and two "twin"s) and a two-link robot "arm" with two drivers
core::WorldDesc TestWorld() {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  world.terrains[0].name = "floor";
  world.objects.push_back(test::BoxObject(0.1, 1.0, Vec3(0, 0, 0.05)));
  world.objects[0].name = "block";
  world.objects[0].sim.surface.friction = 0.5;
  for (int i = 0; i < 2; ++i) {
    world.objects.push_back(test::SphereObject(0.05, 1.0, Vec3(1 + i, 0, 0.05)));
    world.objects.back().name = "twin";
  }
  core::RobotDesc robot;
  robot.name = "arm";
  robot.links.resize(2);
  robot.links[0].name = "base";
  robot.links[1].name = "elbow";
  robot.links[1].parent = 0;
  robot.drivers.resize(2);
  for (int d = 0; d < 2; ++d) {
    robot.drivers[d].name = d == 0 ? "shoulder_motor" : "elbow_motor";
    robot.drivers[d].links = {d};
    robot.drivers[d].servo_p = 10.0 * (d + 1);
  }
  robot.config = core::VecX::Zero(2);
  robot.velocity = core::VecX::Zero(2);
  world.robots.push_back(robot);
  return world;
}

core::VecX Vector(std::initializer_list<double> values) {
  return Eigen::Map<const core::VecX>(values.begin(), static_cast<Eigen::Index>(values.size()));
}

std::string ParseError(const std::string& text) {
  std::string error;
  EXPECT_FALSE(core::ParseAccessPath(text, &error)) << text;
  return error;
}

std::string GetError(const core::WorldDesc& world, const std::string& path) {
  std::string error;
  EXPECT_FALSE(core::GetPath(world, path, &error)) << path;
  return error;
}

// a refused set must leave the world as it was
std::string SetError(const std::string& path, const std::string& value) {
  core::WorldDesc world = TestWorld();
  std::string error;
  EXPECT_FALSE(core::SetPathText(&world, path, value, &error)) << path << "=" << value;
  EXPECT_TRUE(core::CompareWorlds(world, TestWorld()).empty()) << path << "=" << value;
  return error;
}

ParamValue Get(const core::WorldDesc& world, const std::string& path) {
  std::string error;
  const std::optional<ParamValue> value = core::GetPath(world, path, &error);
  EXPECT_TRUE(value) << error;
  return value.value_or(ParamValue{});
}

void Set(core::WorldDesc* world, const std::string& path, const std::string& value) {
  std::string error;
  EXPECT_TRUE(core::SetPathText(world, path, value, &error)) << path << ": " << error;
}

// ---- syntax -------------------------------------------------------------------------------

TEST(AccessPathTest, ParsesSegmentsIndicesAndNames) {
  std::string error;
  const auto path = core::ParseAccessPath("  robots[0].drivers[knee_motor].servoP ", &error);
  ASSERT_TRUE(path) << error;
  EXPECT_EQ(path->text, "robots[0].drivers[knee_motor].servoP");
  ASSERT_EQ(path->segments.size(), 3u);
  EXPECT_EQ(path->segments[0].name, "robots");
  ASSERT_EQ(path->segments[0].selectors.size(), 1u);
  EXPECT_TRUE(path->segments[0].selectors[0].is_index);
  EXPECT_EQ(path->segments[0].selectors[0].index, 0);
  EXPECT_FALSE(path->segments[1].selectors[0].is_index);
  EXPECT_EQ(path->segments[1].selectors[0].name, "knee_motor");
  EXPECT_TRUE(path->segments[2].selectors.empty());
  EXPECT_EQ(path->Prefix(path->segments[1].selectors[0].end), "robots[0].drivers[knee_motor]");
}

TEST(AccessPathTest, QuotedNamesKeepDotsBracketsQuotesAndDigits) {
  std::string error;
  const auto path =
      core::ParseAccessPath(R"(objects['box.1'].x[ "a]b" ].y["it's"].z['0'].w[ my box ])", &error);
  ASSERT_TRUE(path) << error;
  ASSERT_EQ(path->segments.size(), 5u);
  EXPECT_EQ(path->segments[0].selectors[0].name, "box.1");
  EXPECT_EQ(path->segments[1].selectors[0].name, "a]b");
  EXPECT_EQ(path->segments[2].selectors[0].name, "it's");
  // a quoted number is a name, not an index
  EXPECT_FALSE(path->segments[3].selectors[0].is_index);
  EXPECT_EQ(path->segments[3].selectors[0].name, "0");
  // unquoted names run to ']' and lose the blanks around them
  EXPECT_EQ(path->segments[4].selectors[0].name, "my box");
}

TEST(AccessPathTest, BadSyntaxIsRefusedWithTheColumn) {
  EXPECT_EQ(ParseError("  "), "empty access path");
  EXPECT_EQ(ParseError("robots[0"), "robots[0: expected ']' at column 9");
  EXPECT_EQ(ParseError("robots[0]..config"), "robots[0]..config: expected a name at column 11");
  EXPECT_EQ(ParseError("robots[0]."), "robots[0].: expected a name at column 11");
  EXPECT_EQ(ParseError("robots[]"), "robots[]: empty [] at column 8");
  EXPECT_EQ(ParseError("robots['a].x"), "robots['a].x: unterminated quote at column 8");
  EXPECT_EQ(ParseError("robots['a'b].x"),
            "robots['a'b].x: expected ']' after the quoted name at column 11");
  EXPECT_EQ(ParseError("robots[0]x"), "robots[0]x: expected '.' or '[' at column 10");
  EXPECT_EQ(ParseError("3robots"), "3robots: expected a name at column 1");
  EXPECT_EQ(ParseError("objects[99999999999].mass"),
            "objects[99999999999].mass: index 99999999999 is too large at column 9");
}

TEST(AccessPathTest, AssignmentsSplitAtTheFirstEqualsOutsideSelectors) {
  std::string path, value, error;
  ASSERT_TRUE(core::SplitAssignment("objects['a=b'].kFriction = 0.1", &path, &value, &error));
  EXPECT_EQ(path, "objects['a=b'].kFriction");
  EXPECT_EQ(value, "0.1");
  ASSERT_TRUE(core::SplitAssignment("objects[a=b].kFriction=1", &path, &value, &error));
  EXPECT_EQ(path, "objects[a=b].kFriction");
  EXPECT_FALSE(core::SplitAssignment("settings.gravity", &path, &value, &error));
  EXPECT_EQ(error, "'settings.gravity': expected PATH=VALUE");
  EXPECT_FALSE(core::SplitAssignment("=1", &path, &value, &error));
  EXPECT_EQ(error, "'=1': no path before '='");
  EXPECT_FALSE(core::SplitAssignment("settings.gravity= ", &path, &value, &error));
  EXPECT_EQ(error, "'settings.gravity= ': no value after '='");
}

// ---- every kind of row ---------------------------------------------------------------------

TEST(AccessPathTest, RealIntegerBoolAndChoiceRowsAreReadAndWritten) {
  core::WorldDesc world = TestWorld();
  EXPECT_EQ(Get(world, "objects[block].kFriction"), ParamValue{0.5});
  Set(&world, "objects[block].kFriction", "0.1");
  EXPECT_EQ(world.objects[0].sim.surface.friction, 0.1);
  Set(&world, "settings.maxContacts", "7");
  EXPECT_EQ(world.settings.max_contacts, 7);
  Set(&world, "settings.sleeping", "true");
  EXPECT_TRUE(world.settings.sleeping);
  Set(&world, "settings.solver", "quick");
  EXPECT_EQ(world.settings.solver, core::SolverType::kQuickStep);
  Set(&world, "terrains[floor].preshrink", "copy");
  EXPECT_EQ(world.terrains[0].sim.preshrink, core::Preshrink::kCopy);
  Set(&world, "objects[block].kStiffness", "inf");
  EXPECT_EQ(world.objects[0].sim.surface.stiffness, core::kInf);
  EXPECT_EQ(Get(world, "settings.solver"), ParamValue{1.0});
}

TEST(AccessPathTest, VectorRangeAndInertiaRowsAreReadAndWritten) {
  core::WorldDesc world = TestWorld();
  EXPECT_EQ(Get(world, "settings.gravity"), (ParamValue{0, 0, -9.8}));
  Set(&world, "settings.gravity", "0,0,-1.62");
  EXPECT_EQ(world.settings.gravity, Vec3(0, 0, -1.62));
  Set(&world, "objects[0].com", "0.01,0,-0.02");
  EXPECT_EQ(world.objects[0].com, Vec3(0.01, 0, -0.02));
  Set(&world, "robots[arm].links[elbow].jointLimits", "-1,inf");
  EXPECT_EQ(world.robots[0].links[1].q_min, -1.0);
  EXPECT_EQ(world.robots[0].links[1].q_max, core::kInf);
  Set(&world, "robots[0].drivers[elbow_motor].torqueLimits", "-5,5");
  EXPECT_EQ(world.robots[0].drivers[1].torque_min, -5.0);
  EXPECT_EQ(world.robots[0].drivers[1].torque_max, 5.0);
  // three numbers are the diagonal
  Set(&world, "objects[block].inertia", "1,2,3");
  EXPECT_EQ(world.objects[0].inertia, Vec3(1, 2, 3).asDiagonal().toDenseMatrix());
}

// initial conditions are rows on a description: se3 and twist in Klamp't's orders
TEST(AccessPathTest, InitialConditionsAreRowsInKlamptOrder) {
  core::WorldDesc world = TestWorld();
  // a quarter turn about z (x -> y): columns (0,1,0), (-1,0,0), (0,0,1); then the translation
  Set(&world, "rigidObjects[block].transform", "0,1,0, -1,0,0, 0,0,1, 1,2,3");
  const core::Pose& pose = world.objects[0].pose;
  EXPECT_EQ(pose.linear() * Vec3::UnitX(), Vec3::UnitY());
  EXPECT_EQ(pose.translation(), Vec3(1, 2, 3));
  // angular, then linear
  Set(&world, "objects[block].velocity", "0,0,1, 2,0,0");
  EXPECT_EQ(world.objects[0].initial_velocity.angular, Vec3(0, 0, 1));
  EXPECT_EQ(world.objects[0].initial_velocity.linear, Vec3(2, 0, 0));
  Set(&world, "robots[arm].config", "0.1,0.2");
  EXPECT_EQ(world.robots[0].config, Vector({0.1, 0.2}));
  Set(&world, "robots[arm].velocity", "-1,1");
  EXPECT_EQ(world.robots[0].velocity, Vector({-1, 1}));
  EXPECT_EQ(Get(world, "objects[block].transform")[9], 1.0);
}

TEST(AccessPathTest, ServoGainsAnswerToKlamptsLabels) {
  core::WorldDesc world = TestWorld();
  EXPECT_EQ(Get(world, "robots[arm].drivers[1].kP"), ParamValue{20.0});
  Set(&world, "robots[arm].drivers[1].kP", "35");
  Set(&world, "robots[arm].drivers[1].kI", "2");
  Set(&world, "robots[arm].drivers[1].kD", "3");
  EXPECT_EQ(world.robots[0].drivers[1].servo_p, 35.0);
  EXPECT_EQ(world.robots[0].drivers[1].servo_i, 2.0);
  EXPECT_EQ(world.robots[0].drivers[1].servo_d, 3.0);
  EXPECT_EQ(Get(world, "robots[arm].drivers[1].servoP"), ParamValue{35.0});
}

TEST(AccessPathTest, ComponentSetsReadModifyWrite) {
  core::WorldDesc world = TestWorld();
  EXPECT_EQ(Get(world, "settings.gravity[2]"), ParamValue{-9.8});
  Set(&world, "settings.gravity[0]", "1.5");
  EXPECT_EQ(world.settings.gravity, Vec3(1.5, 0, -9.8));
  Set(&world, "robots[0].config[1]", "0.5");
  EXPECT_EQ(world.robots[0].config, Vector({0.0, 0.5}));
  Set(&world, "objects[0].transform[11]", "0.2");
  EXPECT_EQ(world.objects[0].pose.translation(), Vec3(0, 0, 0.2));
  // a component that would break the rule is refused like the whole value
  EXPECT_EQ(SetError("settings.gravity[1]", "nan"),
            "settings.gravity[1] must be 3 finite numbers, got 0,nan,-9.8");
}

// every row of the table is reachable at the path of its element (ElementPath writes access
// paths), reads what GetParam reads, and takes its own formatted value back unchanged
TEST(AccessPathTest, EveryRowIsReachableAndRoundTripsAsText) {
  const core::WorldDesc world = TestWorld();
  const core::ElementIndex elements[] = {
      core::ElementIndex::Settings(), core::ElementIndex::Terrain(0),
      core::ElementIndex::Object(0),  core::ElementIndex::Robot(0),
      core::ElementIndex::Link(0, 1), core::ElementIndex::Driver(0, 1)};
  std::set<const core::ParamSpec*> seen;
  for (const core::ElementIndex& element : elements) {
    for (const core::ParamSpec* row : core::ParamsOf(element.kind)) {
      const std::string path = core::ElementPath(element) + "." + std::string(row->key);
      SCOPED_TRACE(path);
      std::string error;
      const auto target = core::ResolveAccessPath(world, path, AccessContext::kDescription, &error);
      ASSERT_TRUE(target) << error;
      EXPECT_EQ(target->row, row);
      EXPECT_EQ(target->element, element);
      const ParamValue value = Get(world, path);
      EXPECT_EQ(value, *core::GetParam(world, element, *row));
      core::WorldDesc copy = world;
      Set(&copy, path, core::FormatAccessValue(*target, value));
      EXPECT_TRUE(core::CompareWorlds(copy, world).empty());
      seen.insert(row);
    }
  }
  EXPECT_EQ(seen.size(), core::Params().size());
}

// ---- errors --------------------------------------------------------------------------------

TEST(AccessPathTest, MissingElementsAreNamedAsWritten) {
  const core::WorldDesc world = TestWorld();
  EXPECT_EQ(GetError(world, "robots[3].config"), "robots[3]: the world has 1 robot");
  EXPECT_EQ(GetError(world, "terrains[2].padding"), "terrains[2]: the world has 1 terrain");
  EXPECT_EQ(GetError(world, "robots[arm].links[7].mass"),
            "robots[arm].links[7]: robot 'arm' has 2 links");
  EXPECT_EQ(GetError(world, "objects[blok].kFriction"),
            "objects[blok]: no object is named 'blok' (did you mean 'block'?)");
  EXPECT_EQ(GetError(world, "robots[0].links[elbo].mass"),
            "robots[0].links[elbo]: no link of robot 'arm' is named 'elbo' (did you mean "
            "'elbow'?)");
  EXPECT_EQ(GetError(world, "robots[ARM].config"),
            "robots[ARM]: no robot is named 'ARM' (did "
            "you mean 'arm'?)");
  EXPECT_EQ(GetError(world, "objects[twin].mass"),
            "objects[twin]: 2 objects are named 'twin' (indices 1, 2); select one by index");
  EXPECT_EQ(GetError(world, "objects.kFriction"),
            "objects: select an object by index or name: objects[0] or objects[name]");
  EXPECT_EQ(GetError(world, "objects[0][1].kFriction"),
            "objects[0][1]: one [index or name] selects an object");
  EXPECT_EQ(GetError(world, "settings[0].gravity"), "settings[0]: settings takes no [selector]");
}

TEST(AccessPathTest, UnknownItemsSuggestTheNearestName) {
  const core::WorldDesc world = TestWorld();
  EXPECT_EQ(GetError(world, "objects[0].kFrction"),
            "objects[0].kFrction: objects have no 'kFrction' (did you mean 'kFriction'?)");
  // Klamp't's k prefix
  EXPECT_EQ(GetError(world, "terrains[0].friction"),
            "terrains[0].friction: terrains have no 'friction' (did you mean 'kFriction'?)");
  EXPECT_EQ(GetError(world, "settings.gravty"),
            "settings.gravty: settings have no 'gravty' (did you mean 'gravity'?)");
  EXPECT_EQ(GetError(world, "robots[0].drivers[0].kq"),
            "robots[0].drivers[0].kq: drivers have no 'kq' (did you mean 'kP'?)");
  EXPECT_EQ(GetError(world, "objekts[0].mass"),
            "objekts: no such root (roots: settings, terrains, objects, rigidObjects, robots) "
            "(did you mean 'objects'?)");
  EXPECT_EQ(GetError(world, "objects[0]"),
            "objects[0]: names an object, not a value; add an item, e.g. objects[0].kFriction");
  EXPECT_EQ(GetError(world, "settings"),
            "settings: names the settings, not a value; add an item, e.g. settings.gravity");
  EXPECT_EQ(GetError(world, "objects[0].kFriction.x"),
            "objects[0].kFriction.x: kFriction has no members");
}

TEST(AccessPathTest, SimulationItemsAreRefusedOnADescription) {
  const core::WorldDesc world = TestWorld();
  EXPECT_EQ(GetError(world, "controllers[0].commandedConfig"),
            "controllers: exists only on a running simulation");
  EXPECT_EQ(GetError(world, "time"), "time: exists only on a running simulation");
  EXPECT_EQ(GetError(world, "robots[0].actualConfig"),
            "robots[0].actualConfig: exists only on a running simulation");
  EXPECT_EQ(GetError(world, "robots[0].links[1].transform"),
            "robots[0].links[1].transform: exists only on a running simulation");
  // resolved for a simulation, the controllers' items are read-only, and a description cannot
  // take a state item at all
  std::string error;
  const auto commanded = core::ResolveAccessPath(world, "controllers[arm].commandedConfig",
                                                 AccessContext::kSimulation, &error);
  ASSERT_TRUE(commanded) << error;
  EXPECT_TRUE(commanded->read_only);
  EXPECT_EQ(commanded->state, core::StateItem::kCommandedConfig);
  core::WorldDesc copy = world;
  EXPECT_FALSE(core::SetPath(&copy, *commanded, {0, 0}, &error));
  EXPECT_EQ(error, "controllers[arm].commandedConfig: read-only");
  const auto config = core::ResolveAccessPath(world, "robots[arm].actualConfig",
                                              AccessContext::kSimulation, &error);
  ASSERT_TRUE(config) << error;
  EXPECT_FALSE(core::SetPath(&copy, *config, {0, 0}, &error));
  EXPECT_EQ(error, "robots[arm].actualConfig: exists only on a running simulation");
  EXPECT_TRUE(core::CompareWorlds(copy, world).empty());
}

TEST(AccessPathTest, ValuesOutsideTheRulesAreRefusedAndChangeNothing) {
  EXPECT_EQ(SetError("objects[block].kRestitution", "1.5"),
            "objects[block].kRestitution must be in [0, 1], got 1.5");
  EXPECT_EQ(SetError("settings.gravity", "nan,0,0"),
            "settings.gravity must be 3 finite numbers, got nan,0,0");
  EXPECT_EQ(SetError("settings.gravity", "1,2"),
            "settings.gravity must be 3 finite numbers, got 1,2 (2 numbers, needs 3)");
  EXPECT_EQ(SetError("settings.timestep", "0"), "settings.timestep must be > 0, got 0");
  EXPECT_EQ(SetError("objects[0].transform", "2,0,0, 0,1,0, 0,0,1, 0,0,0"),
            "objects[0].transform must be 12 finite numbers: a rotation (column-major) and a "
            "translation, got 2,0,0,0,1,0,0,0,1,0,0,0");
  EXPECT_EQ(SetError("robots[arm].config", "0.1"),
            "robots[arm].config must be one finite number per link, got 0.1 (1 numbers, needs 2)");
}

TEST(AccessPathTest, UnreadableValuesAndBadComponentsAreRefused) {
  EXPECT_EQ(SetError("objects[0].kFriction", "abc"),
            "objects[0].kFriction: cannot read 'abc': must be >= 0 (inf allowed)");
  EXPECT_EQ(SetError("settings.solver", "fast"),
            "settings.solver: cannot read 'fast': must be step, quick or newton");
  EXPECT_EQ(SetError("robots[0].config[1]", "1,2"),
            "robots[0].config[1]: cannot read '1,2': must be one number (a component)");
  const core::WorldDesc world = TestWorld();
  EXPECT_EQ(GetError(world, "settings.gravity[3]"),
            "settings.gravity[3]: gravity has 3 components");
  EXPECT_EQ(GetError(world, "settings.gravity[z]"),
            "settings.gravity[z]: a component is selected by its index");
  EXPECT_EQ(GetError(world, "settings.gravity[0][1]"),
            "settings.gravity[0][1]: one [index] selects a component");
  EXPECT_EQ(GetError(world, "objects[0].kFriction[0]"),
            "objects[0].kFriction[0]: kFriction is one number; it has no components");
}

}  // namespace
}  // namespace lamina
