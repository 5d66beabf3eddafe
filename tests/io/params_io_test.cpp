// SPDX-License-Identifier: MIT
// The parameter table against the files and the simulator, row by row over Params() on the
// fixture world tests/data/params/fixture.xml (a terrain, two objects, a robot with normal and
// affine drivers and joint limits):
//  (a) every row round-trips file -> edit -> save -> load, bit for bit;
//  (b) every reader rejects exactly what the table rejects: each probe value is written raw
//      (spec.set, bypassing the check), and the load reports an error naming the row's
//      attribute iff !ParamAccepts(probe);
//  (c) Simulator::SetParam rejects exactly the same probes, leaving the value unchanged and
//      naming the path.
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/io/param_text.h"
#include "core/io/paths.h"
#include "core/io/world_file.h"
#include "core/model/element.h"
#include "core/model/params.h"
#include "core/model/world_compare.h"
#include "core/number_text.h"
#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::ElementIndex;
using core::ElementKind;
using core::ParamSpec;
using core::ParamType;
using core::ParamValue;
using test::LoadedWorld;

constexpr double kInf = std::numeric_limits<double>::infinity();
// world XML holds a rotation as rotateMoment, read back through the exponential map, which
// reproduces a rotation matrix to a few ulps; every other number is written exactly
constexpr double kRotationTolerance = 1e-14;

const core::WorldDesc& Fixture() {
  static const core::WorldDesc world = [] {
    LoadedWorld loaded;
    test::LoadWorld(test::DataPath("params/fixture.xml"), &loaded);
    EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
    EXPECT_EQ(loaded.diagnostics.warning_count(), 0) << loaded.diagnostics.FormatAll();
    return loaded.world;
  }();
  return world;
}

// every element of `world` that `spec` belongs to
std::vector<ElementIndex> ElementsOf(const core::WorldDesc& world, const ParamSpec& spec) {
  std::vector<ElementIndex> all = {ElementIndex::Settings()};
  for (int i = 0; i < static_cast<int>(world.terrains.size()); ++i) {
    all.push_back(ElementIndex::Terrain(i));
  }
  for (int i = 0; i < static_cast<int>(world.objects.size()); ++i) {
    all.push_back(ElementIndex::Object(i));
  }
  for (int r = 0; r < static_cast<int>(world.robots.size()); ++r) {
    all.push_back(ElementIndex::Robot(r));
    for (int i = 0; i < world.robots[r].dof(); ++i) all.push_back(ElementIndex::Link(r, i));
    for (int i = 0; i < static_cast<int>(world.robots[r].drivers.size()); ++i) {
      all.push_back(ElementIndex::Driver(r, i));
    }
  }
  std::vector<ElementIndex> elements;
  for (const ElementIndex& element : all) {
    if (spec.AppliesTo(element.kind)) elements.push_back(element);
  }
  return elements;
}

// same size and the same bits in every component (NaN included)
bool SameBits(const ParamValue& a, const ParamValue& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

std::string Text(const ParamValue& value) {
  std::string text;
  for (double x : value) text += (text.empty() ? "" : ",") + core::FormatDouble(x);
  return text;
}

std::string Describe(const ParamSpec& spec, const ElementIndex& element, const ParamValue& v) {
  return core::ElementPath(element) + "." + std::string(spec.key) + " = " + Text(v);
}

// ---- (a) valid values different from the fixture's ---------------------------------------

double OtherReal(const ParamSpec& spec, double current) {
  if (std::isfinite(spec.max)) {
    const double candidate = spec.min + 0.37 * (spec.max - spec.min);
    return candidate == current ? spec.min + 0.61 * (spec.max - spec.min) : candidate;
  }
  return std::isfinite(current) ? 1.5 * current + 0.125 : 12.5;
}

ParamValue PoseValue() {
  core::Pose pose = core::Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(0.3, core::Vec3(1, 2, 3).normalized()).toRotationMatrix();
  pose.translation() = core::Vec3(0.25, -0.5, 1.75);
  return core::PoseToValue(pose);
}

ParamValue OtherVector(int size, double start, double step) {
  ParamValue value;
  for (int i = 0; i < size; ++i) value.push_back(start + step * i);
  return value;
}

// A valid value of `spec` that differs from `current` in every component. Torque limits are
// symmetric: a .rob gives a normal driver +-torquemax of its link.
ParamValue OtherValue(const ParamSpec& spec, const ParamValue& current) {
  switch (spec.type) {
    case ParamType::kBool:
      return {current[0] == 0.0 ? 1.0 : 0.0};
    case ParamType::kChoice:
      return {std::fmod(current[0] + 1.0, static_cast<double>(spec.choices.size()))};
    case ParamType::kInteger:
      return {current[0] + 3.0};
    case ParamType::kVec3:
      return {current[0] + 0.125, current[1] - 0.25, current[2] + 0.5};
    case ParamType::kRange:
      if (spec.key == "torqueLimits") return {-7.25, 7.25};
      return spec.key == "jointLimits" ? ParamValue{-1.25, 0.75} : ParamValue{-2.5, 3.25};
    case ParamType::kPose:
      return PoseValue();
    case ParamType::kTwist:
      return {0.125, 0.25, -0.5, 1.0, -2.0, 0.375};
    case ParamType::kInertia:
      return {0.3, 0.01, 0, 0.01, 0.2, 0.02, 0, 0.02, 0.1};
    case ParamType::kVector:
      return OtherVector(static_cast<int>(current.size()), spec.key == "config" ? 0.05 : 0.5,
                         spec.key == "config" ? 0.1 : -0.25);
    case ParamType::kReal:
      return {OtherReal(spec, current[0])};
  }
  return current;
}

// what else an edit changes: nothing. A .rob copies a non-affine driver's limits from its link (q
// from qmin/qmax, velocity from velmin/velmax, torque from torquemax), and the table's setters
// keep both copies equal, so an edit of either comes back on both sides exactly as set.
std::vector<std::string> DerivedFields(const core::WorldDesc&, const ParamSpec&,
                                       const ElementIndex&) {
  return {};
}

bool IsDerived(const std::string& difference, const std::vector<std::string>& fields) {
  for (const std::string& field : fields) {
    if (difference.rfind(field + ":", 0) == 0) return true;
  }
  return false;
}

void ExpectReadBack(const ParamSpec& spec, const ParamValue& expected, const ParamValue& got,
                    const std::string& what) {
  if (spec.type != ParamType::kPose) {
    EXPECT_TRUE(SameBits(got, expected)) << what << " read back as " << Text(got);
    return;
  }
  ASSERT_EQ(got.size(), 12u) << what;
  for (int i = 0; i < 12; ++i) {
    EXPECT_NEAR(got[i], expected[i], i < 9 ? kRotationTolerance : 0.0) << what << " [" << i << "]";
  }
}

TEST(ParamsFileTest, EveryRowRoundTripsFileEditSaveLoad) {
  const std::string path = test::ScratchDir() + "/edited.xml";
  for (const ParamSpec& spec : core::Params()) {
    for (const ElementIndex& element : ElementsOf(Fixture(), spec)) {
      core::WorldDesc edited = Fixture();
      const ParamValue value = OtherValue(spec, *core::GetParam(edited, element, spec));
      const std::string what = Describe(spec, element, value);
      std::string error;
      ASSERT_TRUE(core::SetParam(&edited, element, spec, value, &error)) << what << ": " << error;
      core::Diagnostics diagnostics;
      ASSERT_TRUE(core::SaveWorldFile(edited, path, diagnostics)) << diagnostics.FormatAll();
      LoadedWorld reloaded;
      test::LoadWorld(path, &reloaded);
      ASSERT_TRUE(reloaded.ok) << what << "\n" << reloaded.diagnostics.FormatAll();
      EXPECT_EQ(reloaded.diagnostics.warning_count(), 0) << reloaded.diagnostics.FormatAll();
      ExpectReadBack(spec, value, *core::GetParam(reloaded.world, element, spec), what);
      const auto derived = DerivedFields(edited, spec, element);
      for (const std::string& difference :
           core::CompareWorlds(edited, reloaded.world, kRotationTolerance)) {
        EXPECT_TRUE(IsDerived(difference, derived)) << what << ": " << difference;
      }
    }
  }
}

// ---- the file forms ---------------------------------------------------------------------------

TEST(ParamsFileTest, LaminaGlobalsAreWrittenOnlyWhenTheyDifferFromTheDefaults) {
  core::WorldDesc world = Fixture();
  const std::string path = test::ScratchDir() + "/w.xml";
  EXPECT_THAT(core::WriteWorld(world, path).world_xml,
              ::testing::HasSubstr("<globals timestep=\"0.002\" gravity=\"0 0 -9.8\" ERP=\"0.95\" "
                                   "CFM=\"1e-06\" maxContacts=\"10\" adaptiveTimeStepping=\"1\" "
                                   "rigidObjectCollisions=\"1\" robotSelfCollisions=\"0\" "
                                   "robotRobotCollisions=\"1\"/>"));
  world.settings.solver = core::SolverType::kQuickStep;
  world.settings.sleep_time = 1.5;
  EXPECT_THAT(
      core::WriteWorld(world, path).world_xml,
      ::testing::HasSubstr("robotRobotCollisions=\"1\" solver=\"quick\" sleepTime=\"1.5\"/>"));
}

TEST(ParamsFileTest, LaminaGlobalsAreReadByKeyWithBoolWordsAndChoiceNames) {
  const std::string path = test::WriteScratchFile(
      "w.xml",
      "<world>\n  <simulation>\n    <globals solver=\"quick\" quickStepIterations=\"50\" "
      "sleeping=\"true\" sleepSpeed=\"0.05\" frictionAnchorGain=\"0\" "
      "adaptiveTimeStepping=\"false\"/>\n"
      "  </simulation>\n</world>\n");
  LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_EQ(loaded.diagnostics.warning_count(), 0) << loaded.diagnostics.FormatAll();
  const core::SimSettings& s = loaded.world.settings;
  EXPECT_EQ(s.solver, core::SolverType::kQuickStep);
  EXPECT_EQ(s.quick_step_iterations, 50);
  EXPECT_TRUE(s.sleeping);
  EXPECT_EQ(s.sleep_speed, 0.05);
  EXPECT_EQ(s.friction_anchor_gain, 0.0);
  EXPECT_FALSE(s.adaptive_time_stepping);
}

TEST(ParamsFileTest, WhatAFileCannotHoldIsASaveErrorNotALoss) {
  core::WorldDesc world = Fixture();
  world.robots[0].drivers[0].torque_min = -3.0;  // normal driver: +-torquemax of its link
  world.objects[0].pose.linear() *= 2.0;         // world XML holds rotations only
  core::Diagnostics diagnostics;
  const std::string path = test::ScratchDir() + "/w.xml";
  EXPECT_FALSE(core::SaveWorldFile(world, path, diagnostics));
  EXPECT_EQ(diagnostics.Messages(core::Severity::kError),
            (std::vector<std::string>{
                path + ": error: objects[0].transform: the rotation is not a rotation matrix, "
                       "which world XML (rotateMoment) cannot hold",
                path + ": error: robots[0].drivers[0].torqueLimits -3,40 cannot be saved: a .rob "
                       "gives a non-affine driver the limits +-torquemax of its link"}));
  EXPECT_FALSE(std::filesystem::exists(path));
}

// ---- probes -------------------------------------------------------------------------------

// the numbers a component is probed with: each finite boundary and just outside it, 0, a
// negative number, NaN and both infinities
std::vector<double> ProbeNumbers(const ParamSpec& spec) {
  std::vector<double> numbers = {0.0, -1.0, std::nan(""), kInf, -kInf, 0.5, 2.0};
  const bool whole = spec.type == ParamType::kInteger || spec.type == ParamType::kChoice;
  if (std::isfinite(spec.min)) {
    numbers.push_back(spec.min);
    numbers.push_back(whole ? spec.min - 1 : std::nextafter(spec.min, -kInf));
  }
  if (std::isfinite(spec.max)) {
    numbers.push_back(spec.max);
    numbers.push_back(whole ? spec.max + 1 : std::nextafter(spec.max, kInf));
  }
  return numbers;
}

// the components probed: the first, and for poses the first of the translation
std::vector<size_t> ProbedComponents(const ParamSpec& spec) {
  if (spec.type == ParamType::kPose) return {0, 9};
  if (spec.type == ParamType::kRange || spec.type == ParamType::kInertia) return {0, 1};
  return {0};
}

// The shape failures the table names: wrong size, an unordered range, a matrix that is not a
// rotation, asymmetric and indefinite inertias, a symmetric range around each probe number.
std::vector<ParamValue> ShapeProbes(const ParamSpec& spec, const ParamValue& valid) {
  std::vector<ParamValue> probes = {ParamValue(valid.begin(), valid.end() - 1), valid};
  probes.back().push_back(0.0);
  if (spec.type == ParamType::kRange) {
    probes.push_back({1.0, 0.0});
    for (double x : ProbeNumbers(spec)) probes.push_back({-x, x});
  }
  if (spec.type == ParamType::kPose) probes.push_back(ParamValue(valid.size(), 0.5));
  if (spec.type == ParamType::kInertia) {
    probes.push_back({1, 0.5, 0, 0, 1, 0, 0, 0, 1});
    probes.push_back({1, 0, 0, 0, -1, 0, 0, 0, 1});
  }
  return probes;
}

std::vector<ParamValue> Probes(const ParamSpec& spec, const ParamValue& valid) {
  std::vector<ParamValue> probes;
  for (size_t component : ProbedComponents(spec)) {
    for (double x : ProbeNumbers(spec)) {
      probes.push_back(valid);
      probes.back()[component] = x;
    }
  }
  for (ParamValue& probe : ShapeProbes(spec, valid)) probes.push_back(std::move(probe));
  return probes;
}

// ---- (b) readers ----------------------------------------------------------------------------

// Probes that reached a reader or setter, accepted and refused ones; every row must have both,
// so that no row is skipped whole.
struct Checked {
  int accepted = 0, refused = 0;
};

// Whether the file can say `probe` at all. Fixed-size rows have fixed-size fields (only the
// per-link vectors can be given a wrong size). World XML holds a rotation as rotateMoment, so a
// matrix that is not a rotation (or not finite) cannot be written (the writer says so). A .rob
// gives a normal driver the torque limits +-torquemax of its link, so an asymmetric range
// cannot be written for it (the writer says so; the affine driver's statement takes any range).
bool Expressible(const core::WorldDesc& world, const ParamSpec& spec, const ElementIndex& element,
                 const ParamValue& probe) {
  const int size = core::ParamSize(spec, world, element);
  if (spec.type != ParamType::kVector && static_cast<int>(probe.size()) != size) return false;
  if (spec.type == ParamType::kPose && !core::IsRotation(core::ValueToPose(probe).linear())) {
    return false;
  }
  if (spec.key == "torqueLimits" &&
      world.robots[element.index].drivers[element.sub].type != core::DriverType::kAffine) {
    return probe[0] == -probe[1] || (std::isnan(probe[0]) && std::isnan(probe[1]));
  }
  return true;
}

// Whether the description can hold `probe` as it is. Integers, choices and bools are stored as
// int, enum and bool: 2.5, NaN or inf cannot be stored (converting them is undefined), nor can
// a bool other than 0 or 1. Such probes are written as attribute text instead (all these rows
// are XML attributes: <globals> and <geometry preshrink>).
bool HeldRaw(const ParamSpec& spec, const ParamValue& probe) {
  const double x = probe[0];
  switch (spec.type) {
    case ParamType::kBool:
      return x == 0.0 || x == 1.0;
    case ParamType::kInteger:
      return std::isfinite(x) && x == std::floor(x) && std::abs(x) < 1e9;
    case ParamType::kChoice:
      return spec.key == "preshrink" ? std::isfinite(x) && x == std::floor(x) && std::abs(x) < 1e9
                                     : x == 0.0 || x == 1.0 || x == 2.0;  // step, quick, newton
    default:
      return true;
  }
}

// the words an error about the row may name it by: its key, or the file's attributes
std::vector<std::string> NamesOf(const ParamSpec& spec) {
  std::vector<std::string> names = {std::string(spec.key)};
  if (spec.key == "transform") names.insert(names.end(), {"translation", "rotateMoment"});
  if (spec.key == "jointLimits") names.insert(names.end(), {"qmin", "qmax"});
  if (spec.key == "torqueLimits") names.insert(names.end(), {"torquemax", "driver"});
  if (spec.key == "velocityLimits") names.insert(names.end(), {"velmin", "velmax", "driver"});
  return names;
}

bool NamesRow(const std::vector<std::string>& errors, const ParamSpec& spec) {
  for (const std::string& error : errors) {
    for (const std::string& name : NamesOf(spec)) {
      if (error.find(name) != std::string::npos) return true;
    }
  }
  return false;
}

// writes every file of WriteWorld as it is, what the writer would refuse to save included
void WriteFiles(const core::WorldDesc& world, const std::string& path) {
  const core::WorldFileSet files = core::WriteWorld(world, path);
  for (const auto* group : {&files.geometry_files, &files.robot_files}) {
    for (const auto& [file, text] : *group) {
      std::filesystem::create_directories(std::filesystem::path(file).parent_path());
      std::ofstream(file, std::ios::binary) << text;
    }
  }
  std::ofstream(path, std::ios::binary) << files.world_xml;
}

// The files of `world` with `probe` set raw, or, when the description cannot hold it, of
// `world` with a valid value of its own on `element` whose attribute text is then replaced by
// the probe's.
void WriteProbe(const ParamSpec& spec, const ElementIndex& element, const ParamValue& probe,
                const std::string& path) {
  core::WorldDesc world = Fixture();
  if (HeldRaw(spec, probe)) {
    spec.set(&world, element, probe);
    ASSERT_TRUE(spec.type == ParamType::kVector || SameBits(spec.get(world, element), probe))
        << Describe(spec, element, probe) << " is not held raw";
    WriteFiles(world, path);
    return;
  }
  const ParamValue own = OtherValue(spec, spec.get(world, element));
  spec.set(&world, element, own);
  WriteFiles(world, path);
  std::string xml;
  ASSERT_TRUE(core::ReadFileText(path, &xml));
  const std::string from = std::string(spec.key) + "=\"" + core::ParamWords(spec, own) + "\"";
  const size_t at = xml.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  ASSERT_EQ(xml.find(from, at + 1), std::string::npos) << from << " is not unique";
  xml.replace(at, from.size(), std::string(spec.key) + "=\"" + Text(probe) + "\"");
  std::ofstream(path, std::ios::binary) << xml;
}

// writes the world with `probe` and loads it: an error naming the row iff the table refuses it
void ExpectReaderAgrees(const ParamSpec& spec, const ElementIndex& element, const ParamValue& probe,
                        const std::string& path, Checked* checked) {
  WriteProbe(spec, element, probe, path);
  LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  const bool accepted = core::ParamAccepts(spec, probe, core::ParamSize(spec, Fixture(), element));
  const std::string what = Describe(spec, element, probe);
  const auto errors = loaded.diagnostics.Messages(core::Severity::kError);
  ++(accepted ? checked->accepted : checked->refused);
  EXPECT_EQ(loaded.ok, accepted) << what << "\n" << loaded.diagnostics.FormatAll();
  if (!accepted) {
    EXPECT_TRUE(NamesRow(errors, spec)) << what << "\n" << loaded.diagnostics.FormatAll();
  } else if (loaded.ok && spec.type == ParamType::kPose) {
    ExpectReadBack(spec, probe, spec.get(loaded.world, element), what);
  } else if (loaded.ok) {
    // equal as numbers: FormatDouble writes -0 as 0 (the symmetric probe around 0 is -0,0)
    EXPECT_EQ(spec.get(loaded.world, element), probe) << what;
  }
}

TEST(ParamsFileTest, EveryReaderRejectsExactlyWhatTheTableRejects) {
  const std::string path = test::ScratchDir() + "/probe.xml";
  for (const ParamSpec& spec : core::Params()) {
    Checked checked;
    for (const ElementIndex& element : ElementsOf(Fixture(), spec)) {
      for (const ParamValue& probe : Probes(spec, spec.get(Fixture(), element))) {
        if (!Expressible(Fixture(), spec, element, probe)) continue;
        ExpectReaderAgrees(spec, element, probe, path, &checked);
      }
    }
    EXPECT_GT(checked.accepted, 0) << spec.key;
    EXPECT_GT(checked.refused, 0) << spec.key;
  }
}

// ---- (c) the simulator's setter -------------------------------------------------------------

void ExpectSetterAgrees(core::Simulator* simulator, const ParamSpec& spec,
                        const ElementIndex& element, const ParamValue& probe, Checked* checked) {
  const ParamValue before = *simulator->GetParam(element, spec);
  // the table's rule on this element (a non-affine driver's torque limits are also symmetric,
  // the only values a .rob can give it: the probes (b) skips as inexpressible)
  const bool accepted = !core::CheckParamOn(Fixture(), element, spec, probe);
  const std::string what = Describe(spec, element, probe);
  ++(accepted ? checked->accepted : checked->refused);
  std::string error;
  ASSERT_EQ(simulator->SetParam(element, spec, probe, &error), accepted) << what << ": " << error;
  if (accepted) {
    EXPECT_TRUE(SameBits(*simulator->GetParam(element, spec), probe)) << what;
    ASSERT_TRUE(simulator->SetParam(element, spec, before, &error)) << what << ": " << error;
    return;
  }
  EXPECT_TRUE(SameBits(*simulator->GetParam(element, spec), before)) << what;
  const std::string path = core::ElementPath(element) + "." + std::string(spec.key);
  EXPECT_THAT(error, ::testing::StartsWith(path + " ")) << what;
}

TEST(ParamsSimulatorTest, EverySetterRejectsExactlyWhatTheReaderRejects) {
  for (const ParamSpec& spec : core::Params()) {
    Checked checked;
    for (const ElementIndex& element : ElementsOf(Fixture(), spec)) {
      core::Simulator simulator(Fixture());
      for (const ParamValue& probe : Probes(spec, spec.get(Fixture(), element))) {
        ExpectSetterAgrees(&simulator, spec, element, probe, &checked);
      }
    }
    EXPECT_GT(checked.accepted, 0) << spec.key;
    EXPECT_GT(checked.refused, 0) << spec.key;
  }
}

}  // namespace
}  // namespace lamina
