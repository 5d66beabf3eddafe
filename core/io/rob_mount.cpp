// SPDX-License-Identifier: MIT
// `.rob` assembly: mounted geometry, automass and mounted sub-robots.
#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/mass_properties.h"
#include "core/io/geometry_file.h"
#include "core/io/paths.h"
#include "core/io/rob_statements.h"
#include "core/io/text_statements.h"

namespace lamina::core::rob {

namespace {

bool IsRobotFile(const std::string& file) {
  const std::string extension = LowerExtension(file);
  return extension == "rob" || extension == "urdf";
}

// mass properties of all of a link's geometry (own file and mounted meshes) together
MassProperties LinkMassProperties(const LinkDesc& link, double mass, double surface_fraction) {
  std::vector<const GeometryDesc*> parts;
  for (const GeometryDesc& geometry : link.geometry) {
    if (!geometry.empty()) parts.push_back(&geometry);
  }
  if (parts.size() == 1) return ComputeMassProperties(*parts.front(), mass, surface_fraction);
  TriangleMesh merged;
  for (const GeometryDesc* geometry : parts) {
    const TriangleMesh baked = BakedMesh(*geometry);
    const int offset = merged.vertex_count();
    merged.vertices.insert(merged.vertices.end(), baked.vertices.begin(), baked.vertices.end());
    for (const Eigen::Vector3i& triangle : baked.triangles) {
      merged.triangles.push_back(triangle + Eigen::Vector3i::Constant(offset));
    }
  }
  return ComputeMassProperties(merged, mass, surface_fraction);
}

// all pairs (i < j) of links with geometry that are not parent and child
std::vector<std::pair<int, int>> DefaultPairs(const RobotDesc& robot) {
  RobotDesc copy;
  copy.links = robot.links;
  return copy.SelfCollisionPairs();
}

// Merges the self-collision lists of `sub` (links from `offset` on, mounted on `link`) into
// `robot`. When either side has an explicit list the default pairs of the other side and the
// pairs across the two are made explicit too, so the merged list means what both did.
void MergeSelfCollision(const RobotDesc& sub, int link, int offset, RobotDesc* robot) {
  const auto shifted = [offset](std::pair<int, int> pair) {
    return std::make_pair(pair.first + offset, pair.second + offset);
  };
  for (const auto& pair : sub.no_self_collision) robot->no_self_collision.push_back(shifted(pair));
  if (robot->self_collision.empty() && sub.self_collision.empty()) return;
  std::vector<std::pair<int, int>> pairs = robot->self_collision;
  if (pairs.empty()) {
    RobotDesc original;
    original.links.assign(robot->links.begin(), robot->links.begin() + offset);
    pairs = DefaultPairs(original);
  }
  const auto sub_pairs = sub.self_collision.empty() ? DefaultPairs(sub) : sub.self_collision;
  for (const auto& pair : sub_pairs) pairs.push_back(shifted(pair));
  for (int i = 0; i < offset; ++i) {
    if (!robot->links[i].has_geometry()) continue;
    for (int j = 0; j < sub.dof(); ++j) {
      if (!sub.links[j].has_geometry() || (i == link && sub.links[j].parent < 0)) continue;
      pairs.emplace_back(i, j + offset);
    }
  }
  robot->self_collision = std::move(pairs);
}

}  // namespace

bool FindLink(const RobotDesc& robot, const std::string& reference, int* index) {
  if (ParseInt(reference, index)) return true;
  for (int i = 0; i < robot.dof(); ++i) {
    if (robot.links[i].name == reference) {
      *index = i;
      return true;
    }
  }
  return false;
}

std::string OutOfRangeMessage(const std::string& keyword, int link, int count) {
  return "'" + keyword + "' link " + std::to_string(link) + " is out of range (robot has " +
         std::to_string(count) + " links)";
}

std::vector<PairStatement> ResolvePairs(const RobotDesc& robot,
                                        const std::vector<PairStatement>& pairs,
                                        const std::string& keyword, bool final,
                                        const std::string& path, Diagnostics& diagnostics,
                                        std::vector<std::pair<int, int>>* out) {
  enum class Reference { kFound, kUnknown, kOutOfRange };
  const auto resolve = [&robot](const std::string& reference, int* index) {
    if (!FindLink(robot, reference, index)) return Reference::kUnknown;
    return (*index >= 0 && *index < robot.dof()) ? Reference::kFound : Reference::kOutOfRange;
  };
  std::vector<PairStatement> residual;
  for (const PairStatement& pair : pairs) {
    int first = -1, second = -1;
    const Reference a = resolve(pair.first, &first);
    const Reference b = resolve(pair.second, &second);
    const bool found = a == Reference::kFound && b == Reference::kFound;
    const SourceLocation where{path, pair.line, 0};
    if (!found && !final) {
      residual.push_back(pair);
    } else if (!found) {
      const bool first_bad = a != Reference::kFound;
      if ((first_bad ? a : b) == Reference::kUnknown) {
        diagnostics.Error(where, "unknown link '" + (first_bad ? pair.first : pair.second) +
                                     "' in '" + keyword + "'");
      } else {
        diagnostics.Error(where,
                          OutOfRangeMessage(keyword, first_bad ? first : second, robot.dof()));
      }
    } else if (first == second) {  // Klamp't accepts it; a link never collides with itself
      diagnostics.Warning(where, "'" + keyword + "' pair names link " + std::to_string(first) +
                                     " twice ('" + pair.first + "' and '" + pair.second +
                                     "'); ignored");
    } else {
      out->emplace_back(first, second);
    }
  }
  return residual;
}

void MountGeometry(RobBuild& build, const std::vector<int>& mount_links) {
  const std::string directory = DirectoryOf(build.path);
  const std::vector<MountStatement>& mounts = build.statements.mounts;
  for (size_t m = 0; m < mounts.size(); ++m) {
    const MountStatement& mount = mounts[m];
    if (IsRobotFile(mount.file) || mount_links[m] < -1) continue;
    if (mount_links[m] == -1) {
      build.Error(mount.line, "'mount' of a geometry file needs a link, got '-1'");
      continue;
    }
    if (!mount.prefix.empty()) {
      build.Warning(mount.line, "'as " + mount.prefix + "' is ignored for a geometry file");
    }
    GeometryDesc geometry;
    if (!LoadGeometryFile(ResolvePath(directory, mount.file), build.At(mount.line), build.context,
                          &geometry)) {
      continue;
    }
    LinkDesc& link = build.robot.links[mount_links[m]];
    geometry.transform = Affine(mount.transform.matrix());
    if (link.geometry.empty()) link.geometry.emplace_back();  // no own geometry
    const NumberList& margins = build.statements.geom_margin;
    if (!margins.empty()) {
      geometry.margin = margins.size() == 1 ? margins.values[0] : margins.values[mount_links[m]];
    }
    link.geometry.push_back(geometry);
  }
}

void ApplyAutomass(RobBuild& build) {
  const RobStatements& s = build.statements;
  if (!s.automass) return;
  const bool com_given = !s.com.empty();
  const bool inertia_given = !s.inertia.empty() || !s.inertia_diag.empty();
  for (int i = 0; i < build.link_count; ++i) {
    LinkDesc& link = build.robot.links[i];
    if (!link.has_geometry()) {
      // as Klamp't for massless links; a link with mass but no geometry keeps its inertia
      if (!inertia_given && link.mass == 0.0) link.inertia.setZero();
      continue;
    }
    // the COM does not depend on the mass; a massless link still gets its geometric COM
    const double mass = link.mass > 0.0 ? link.mass : 1.0;
    const MassProperties properties = LinkMassProperties(link, mass, s.surface_fraction);
    if (!properties.valid) {
      build.Warning(s.automass_line, "automass: the geometry of link " + std::to_string(i) + " ('" +
                                         link.name +
                                         "') has no volume or area; its mass properties are "
                                         "left as they were");
      continue;
    }
    if (!com_given) link.com = properties.com;
    if (inertia_given) continue;
    if (link.mass == 0.0) {
      link.inertia.setZero();
      continue;
    }
    // about the link's COM, which is the file's when the file gives one (parallel axes)
    const Vec3 offset = properties.com - link.com;
    link.inertia = properties.inertia + link.mass * (offset.squaredNorm() * Mat3::Identity() -
                                                     offset * offset.transpose());
  }
}

void MountRobots(RobBuild& build, const std::vector<int>& mount_links) {
  const std::string directory = DirectoryOf(build.path);
  const std::vector<MountStatement>& mounts = build.statements.mounts;
  for (size_t m = 0; m < mounts.size(); ++m) {
    const MountStatement& mount = mounts[m];
    if (!IsRobotFile(mount.file) || mount_links[m] < -1) continue;
    const std::string file = ResolvePath(directory, mount.file);  // normalized, as the stack
    if (std::find(build.stack.begin(), build.stack.end(), file) != build.stack.end()) {
      build.Error(mount.line, "'mount' of '" + file + "' would mount a robot inside itself");
      continue;
    }
    RobotDesc sub;
    if (!LoadRobotFileNested(file, build.At(mount.line), build.context, build.stack, &sub)) {
      continue;
    }
    if (!sub.properties.empty()) {
      build.Warning(mount.line, "the properties of mounted robot '" + file + "' are ignored");
    }
    MountSubRobot(sub, mount_links[m], mount.transform, mount.prefix, &build.robot);
  }
}

void MountSubRobot(const RobotDesc& sub, int link, const Pose& transform, const std::string& prefix,
                   RobotDesc* robot) {
  const int offset = robot->dof();
  const std::string name_prefix = prefix.empty() ? "" : prefix + ":";
  for (LinkDesc child : sub.links) {
    if (child.parent < 0) {
      child.parent = link;
      child.parent_transform = transform * child.parent_transform;
    } else {
      child.parent += offset;
    }
    child.name = name_prefix + child.name;
    robot->links.push_back(std::move(child));
  }
  for (JointDesc joint : sub.joints) {
    joint.link += offset;
    const bool spans = joint.type == JointType::kFloating ||
                       joint.type == JointType::kFloatingPlanar ||
                       joint.type == JointType::kBallAndSocket;
    if (spans) joint.base = joint.base < 0 ? link : joint.base + offset;
    robot->joints.push_back(joint);
  }
  for (DriverDesc driver : sub.drivers) {
    for (int& driven : driver.links) driven += offset;
    driver.name = name_prefix + driver.name;
    robot->drivers.push_back(std::move(driver));
  }
  MergeSelfCollision(sub, link, offset, robot);
  VecX config(robot->config.size() + sub.config.size());
  config << robot->config, sub.config;
  robot->config = config;
  robot->velocity = VecX::Zero(config.size());
}

}  // namespace lamina::core::rob
