// SPDX-License-Identifier: MIT
// Writing a RobotDesc as a Klamp't `.rob` file. Everything is written explicitly (no automass,
// no defaults left to the reader) so that ParseRob gives back the same description.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/io/paths.h"
#include "core/io/robot_file.h"
#include "core/io/text_statements.h"
#include "core/math_types.h"
#include "core/model/element.h"
#include "core/model/params.h"

namespace lamina::core {

namespace {

std::string Quote(const std::string& text) {
  return "\"" + text + "\"";
}

std::string Numbers(const std::vector<double>& values) {
  return FormatDoubles(values.data(), static_cast<int>(values.size()));
}

std::string Vector3Text(const Vec3& v) {
  return FormatDoubles(v.data(), 3);
}

std::string RowMajor(const Eigen::MatrixXd& m) {
  std::vector<double> values;
  for (int r = 0; r < m.rows(); ++r) {
    for (int c = 0; c < m.cols(); ++c) values.push_back(m(r, c));
  }
  return Numbers(values);
}

// a per-link line: `keyword` then one entry per link, long entries one per line
std::string PerLink(const RobotDesc& robot, const std::string& keyword,
                    const std::function<std::string(const LinkDesc&)>& entry,
                    bool one_per_line = false) {
  std::string line = keyword;
  for (int i = 0; i < robot.dof(); ++i) {
    line += (one_per_line && i > 0) ? " \\\n    " : (i == 0 ? " " : "  ");
    line += entry(robot.links[i]);
  }
  return line + "\n";
}

// a per-driver line of the table's row `spec` (its key is the `.rob` keyword) for the drivers
// of the one robot of `world` (the rows address drivers of a world)
std::string PerDriver(const WorldDesc& world, const ParamSpec& spec) {
  std::vector<double> values;
  for (int i = 0; i < static_cast<int>(world.robots.front().drivers.size()); ++i) {
    values.push_back(spec.get(world, ElementIndex::Driver(0, i)).front());
  }
  return std::string(spec.key) + " " + Numbers(values) + "\n";
}

// The limits a link's `velmin`, `velmax` and `torquemax` carry. A normal, translation or
// rotation driver copies them from its (first) link when the file is read, so they hold that
// driver's own limits (the table's rows velocityLimits and torqueLimits, which an edit may have
// changed); other links keep theirs.
struct LinkLimits {
  double velocity_min, velocity_max, torque_max;
};

// the first geometry of a link that is not empty, or nullptr
const GeometryDesc* FirstGeometry(const LinkDesc& link) {
  for (const GeometryDesc& geometry : link.geometry) {
    if (!geometry.empty()) return &geometry;
  }
  return nullptr;
}

class RobWriter {
 public:
  RobWriter(const RobotDesc& robot, const std::string& rob_dir, std::vector<std::string>* errors)
      : robot_(robot), rob_dir_(rob_dir), errors_(errors) {}

  std::string Write() {
    WriteKinematics();
    WriteLimits();
    WriteMass();
    WriteGeometry();
    WriteJoints();
    WriteDrivers();
    WriteCollisionPairs();
    WriteProperties();
    return notes_ + out_;
  }

 private:
  void WriteKinematics();
  void WriteLimits();
  void WriteMass();
  void WriteGeometry();
  void WriteMounts();
  void WriteJoints();
  void WriteDrivers();
  void WriteCollisionPairs();
  void WriteProperties();
  // the file name of a geometry relative to the .rob, "" (with a note) when it has none
  std::string FileOf(const GeometryDesc& geometry, int link);
  std::vector<LinkLimits> LimitsOfLinks();

  const RobotDesc& robot_;
  const std::string& rob_dir_;
  std::vector<std::string>* errors_;  // what a .rob cannot hold
  std::string notes_;                 // comments at the top about what could not be written
  std::string out_;
};

// what an inline geometry is, for the note that it is not saved
std::string InlineShapeName(const GeometryDesc& geometry) {
  if (geometry.kind == GeometryKind::kPrimitive) return geometry.primitive.TypeName();
  return geometry.kind == GeometryKind::kPointCloud ? "point cloud" : "mesh";
}

std::string RobWriter::FileOf(const GeometryDesc& geometry, int link) {
  if (!geometry.path.empty()) return RelativePath(geometry.path, rob_dir_);
  if (!geometry.empty()) {
    notes_ += "# link " + std::to_string(link) + " ('" + robot_.links[link].name +
              "'): an inline " + InlineShapeName(geometry) + " without a file is not saved\n";
  }
  return "";
}

void RobWriter::WriteKinematics() {
  out_ += PerLink(robot_, "links", [](const LinkDesc& l) { return Quote(l.name); });
  out_ += PerLink(robot_, "parents", [](const LinkDesc& l) { return std::to_string(l.parent); });
  out_ += PerLink(robot_, "jointtype", [](const LinkDesc& l) {
    return std::string(l.axis_type == LinkJointAxis::kPrismatic ? "p" : "r");
  });
  out_ += PerLink(robot_, "axis", [](const LinkDesc& l) { return Vector3Text(l.axis); });
  out_ += PerLink(
      robot_, "tparent",
      [](const LinkDesc& l) {
        const std::array<double, 12> numbers = KlamptNumbersFromPose(l.parent_transform);
        return FormatDoubles(numbers.data(), 12);
      },
      true);
}

std::vector<LinkLimits> RobWriter::LimitsOfLinks() {
  std::vector<LinkLimits> limits;
  for (const LinkDesc& link : robot_.links) {
    limits.push_back({link.velocity_min, link.velocity_max, link.torque_max});
  }
  for (size_t i = 0; i < robot_.drivers.size(); ++i) {
    const DriverDesc& driver = robot_.drivers[i];
    if (driver.type == DriverType::kAffine || driver.links.empty()) continue;
    const int link = driver.links.front();
    if (link < 0 || link >= robot_.dof()) continue;
    limits[link] = {driver.velocity_min, driver.velocity_max, driver.torque_max};
    const bool symmetric = driver.torque_min == -driver.torque_max ||
                           std::isnan(driver.torque_min) || std::isnan(driver.torque_max);
    if (!symmetric && errors_) {
      errors_->push_back("drivers[" + std::to_string(i) + "].torqueLimits " +
                         FormatDouble(driver.torque_min) + "," + FormatDouble(driver.torque_max) +
                         " cannot be saved: a .rob gives a non-affine driver the limits "
                         "+-torquemax of its link");
    }
  }
  return limits;
}

void RobWriter::WriteLimits() {
  const auto scalar = [&](const char* keyword, double LinkDesc::*field) {
    out_ += PerLink(robot_, keyword, [field](const LinkDesc& l) { return FormatDouble(l.*field); });
  };
  const std::vector<LinkLimits> limits = LimitsOfLinks();
  const auto limit = [&](const char* keyword, double LinkLimits::*field) {
    out_ += PerLink(robot_, keyword, [&](const LinkDesc& l) {
      return FormatDouble(limits[&l - robot_.links.data()].*field);
    });
  };
  scalar("q", &LinkDesc::q_initial);
  scalar("qmin", &LinkDesc::q_min);
  scalar("qmax", &LinkDesc::q_max);
  limit("velmin", &LinkLimits::velocity_min);
  limit("velmax", &LinkLimits::velocity_max);
  scalar("accmax", &LinkDesc::acceleration_max);
  limit("torquemax", &LinkLimits::torque_max);
  scalar("powermax", &LinkDesc::power_max);
}

void RobWriter::WriteMass() {
  out_ += PerLink(robot_, "mass", [](const LinkDesc& l) { return FormatDouble(l.mass); });
  out_ += PerLink(robot_, "com", [](const LinkDesc& l) { return Vector3Text(l.com); });
  out_ += PerLink(
      robot_, "inertia", [](const LinkDesc& l) { return RowMajor(l.inertia); }, true);
}

void RobWriter::WriteGeometry() {
  std::string files = "geometry";
  std::vector<double> scales, margins;
  std::string transforms;
  for (int i = 0; i < robot_.dof(); ++i) {
    const LinkDesc& link = robot_.links[i];
    const GeometryDesc* own = link.geometry.empty() ? nullptr : &link.geometry.front();
    // appended piece by piece here and below: GCC 12 at -O3 flags `" " + std::string` with a
    // false -Wrestrict
    files += ' ';
    files += Quote(own ? FileOf(*own, i) : "");
    const GeometryDesc* first = FirstGeometry(link);
    margins.push_back(first ? first->margin : 0.0);
    const bool has_own = own != nullptr && !own->empty();
    // a non-uniform scale is folded into the geomtransform
    const bool uniform = has_own && IsUniformScale(own->scale);
    scales.push_back(uniform ? own->scale.x() : 1.0);
    if (!has_own) continue;
    const Affine matrix = uniform ? own->transform : own->Matrix();
    if (!matrix.matrix().isIdentity(0.0)) {
      transforms += "geomtransform " + std::to_string(i) + " " + RowMajor(matrix.matrix()) + "\n";
    }
  }
  out_ += files + "\n";
  if (std::any_of(scales.begin(), scales.end(), [](double s) { return s != 1.0; })) {
    out_ += "geomscale " + Numbers(scales) + "\n";
  }
  if (std::any_of(margins.begin(), margins.end(), [](double m) { return m != 0.0; })) {
    out_ += "geommargin " + Numbers(margins) + "\n";
  }
  out_ += transforms;
  WriteMounts();
}

void RobWriter::WriteMounts() {
  for (int i = 0; i < robot_.dof(); ++i) {
    const std::vector<GeometryDesc>& geometry = robot_.links[i].geometry;
    for (size_t g = 1; g < geometry.size(); ++g) {
      const std::string file = FileOf(geometry[g], i);
      if (file.empty()) continue;
      const Affine matrix = geometry[g].Matrix();
      std::vector<double> numbers;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) numbers.push_back(matrix.linear()(r, c));
      }
      for (int r = 0; r < 3; ++r) numbers.push_back(matrix.translation()[r]);
      out_ += "mount " + std::to_string(i) + " " + Quote(file) + " " + Numbers(numbers) + "\n";
    }
  }
}

void RobWriter::WriteJoints() {
  for (const JointDesc& joint : robot_.joints) {
    const std::string link = std::to_string(joint.link);
    std::string base = " ";
    base += std::to_string(joint.base);
    switch (joint.type) {
      case JointType::kNormal:
        out_ += "joint normal " + link + "\n";
        break;
      case JointType::kSpin:
        out_ += "joint spin " + link + "\n";
        break;
      case JointType::kWeld:
        out_ += "joint weld " + link + "\n";
        break;
      case JointType::kFloating:
        out_ += "joint floating " + link + base + "\n";
        break;
      case JointType::kFloatingPlanar:
        out_ += "joint floatingplanar " + link + base + "\n";
        break;
      case JointType::kBallAndSocket:
        out_ += "joint ballandsocket " + link + base + "\n";
        break;
    }
  }
}

void RobWriter::WriteDrivers() {
  if (robot_.drivers.empty()) return;
  for (const DriverDesc& driver : robot_.drivers) {
    std::string links;
    for (int link : driver.links) {
      links += ' ';
      links += std::to_string(link);
    }
    switch (driver.type) {
      case DriverType::kNormal:
        out_ += "driver normal" + links + "\n";
        break;
      case DriverType::kTranslation:
        out_ += "driver translation" + links + "\n";
        break;
      case DriverType::kRotation:
        out_ += "driver rotation" + links + "\n";
        break;
      case DriverType::kAffine:
        out_ += "driver affine " + std::to_string(driver.links.size()) + links + "  " +
                Numbers(driver.affine_scale) + "  " + Numbers(driver.affine_offset) + "  " +
                Numbers({driver.q_min, driver.q_max, driver.velocity_min, driver.velocity_max,
                         driver.torque_min, driver.torque_max}) +
                "\n";
        break;
    }
  }
  std::string names = "drivers";
  for (const DriverDesc& driver : robot_.drivers) {
    names += ' ';
    names += Quote(driver.name);
  }
  out_ += names + "\n";
  // one line per single-number driver row (the gains and the friction); the range rows are in
  // the `driver affine` lines or in the links' velmin/velmax/torquemax
  WorldDesc world;
  world.robots.push_back(robot_);
  for (const ParamSpec* spec : ParamsOf(ElementKind::kDriver)) {
    if (spec->type == ParamType::kReal) out_ += PerDriver(world, *spec);
  }
}

void RobWriter::WriteCollisionPairs() {
  const auto pairs = [&](const char* keyword, const std::vector<std::pair<int, int>>& list) {
    if (list.empty()) return;
    std::string line = keyword;
    for (const auto& [first, second] : list) {
      line += "  " + std::to_string(first) + " " + std::to_string(second);
    }
    out_ += line + "\n";
  };
  pairs("selfcollision", robot_.self_collision);
  pairs("noselfcollision", robot_.no_self_collision);
}

// A value that is one line without '"' is written quoted; another single-line value is
// written as is (the reader keeps its text); line breaks, which a .rob statement cannot hold,
// become spaces.
void RobWriter::WriteProperties() {
  for (const auto& [name, value] : robot_.properties) {
    std::string text = value;
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::replace(text.begin(), text.end(), '\r', ' ');
    const bool quotable = text.find('"') == std::string::npos;
    out_ += "property " + name + " " + (quotable ? Quote(text) : text) + "\n";
  }
}

}  // namespace

std::string WriteRob(const RobotDesc& robot, const std::string& rob_dir) {
  return RobWriter(robot, rob_dir, nullptr).Write();
}

std::string WriteRob(const RobotDesc& robot, const std::string& rob_dir,
                     std::vector<std::string>* errors) {
  return RobWriter(robot, rob_dir, errors).Write();
}

}  // namespace lamina::core
