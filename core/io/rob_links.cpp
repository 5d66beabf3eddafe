// SPDX-License-Identifier: MIT
// `.rob` assembly, first half: the link count, the links themselves and their geometry files.
#include <algorithm>
#include <cmath>
#include <map>

#include "core/io/geometry_file.h"
#include "core/io/param_text.h"
#include "core/io/paths.h"
#include "core/io/rob_statements.h"
#include "core/io/text_statements.h"

namespace lamina::core::rob {

namespace {

constexpr double kDegree = kPi / 180.0;

// a per-link vector: `group` numbers per link; `votes` when it takes part in Klamp't's vote
struct PerLinkVector {
  const NumberList* list;
  int group;
  bool votes;
};

std::vector<PerLinkVector> PerLinkVectors(const RobStatements& s) {
  return {{&s.parents, 1, true},
          {&s.mass, 1, true},
          {&s.com, 3, true},
          {&s.inertia, 9, true},
          {&s.inertia_diag, 3, true},
          {&s.a, 1, true},
          {&s.d, 1, true},
          {&s.alpha, 1, true},
          {&s.theta, 1, true},
          {&s.tparent, 12, true},
          {&s.axis, 3, true},
          {&s.q, 1, true},
          {&s.q_min, 1, true},
          {&s.q_max, 1, true},
          {&s.velocity_min, 1, true},
          {&s.velocity_max, 1, true},
          {&s.torque_max, 1, true},
          {&s.power_max, 1, true},
          {&s.acceleration_max, 1, false}};
}

// Klamp't's vote: the most common non-zero length wins, ties going to the smaller length
int Vote(const RobStatements& s) {
  std::map<int, int> votes;
  for (const PerLinkVector& vector : PerLinkVectors(s)) {
    if (vector.votes) ++votes[vector.list->size() / vector.group];
  }
  ++votes[s.link_names.size()];
  ++votes[s.joint_types.size()];
  votes.erase(0);
  int winner = 0, best = 0;
  for (const auto& [length, count] : votes) {
    if (count > best) {
      best = count;
      winner = length;
    }
  }
  return winner;
}

std::string Expected(const std::string& keyword, int n, int group, const char* unit, int got) {
  if (group == 1) {
    return "'" + keyword + "' expects " + CountOf(n, unit) + " (one per link), got " +
           std::to_string(got);
  }
  return "'" + keyword + "' expects " + std::to_string(n * group) + " numbers (" +
         std::to_string(group) + " per link), got " + std::to_string(got);
}

// Klamp't's Denavit-Hartenberg frame: Trans_x(a) Rot_x(alpha) Trans_z(d) Rot_z(theta)
Pose DenavitHartenberg(double alpha, double a, double d, double theta) {
  Pose pose = Pose::Identity();
  pose.linear() =
      (Eigen::AngleAxisd(alpha, Vec3::UnitX()) * Eigen::AngleAxisd(theta, Vec3::UnitZ()))
          .toRotationMatrix();
  pose.translation() = Vec3(a, -std::sin(alpha) * d, std::cos(alpha) * d);
  return pose;
}

// value i of a per-link list, degrees converted for revolute links only
double LinkValue(const NumberList& list, int i, bool revolute) {
  const double value = list.values[i];
  return (list.degrees[i] && revolute) ? value * kDegree : value;
}

// value i of a DH angle list, degrees always converted
double Angle(const NumberList& list, int i) {
  return list.degrees[i] ? list.values[i] * kDegree : list.values[i];
}

Vec3 Triple(const NumberList& list, int i) {
  return {list.values[3 * i], list.values[3 * i + 1], list.values[3 * i + 2]};
}

// entry i of a list with `group` numbers per entry
ParamValue Values(const NumberList& list, int i, int group) {
  return ParamValue(list.values.begin() + group * i, list.values.begin() + group * (i + 1));
}

void BuildTree(RobBuild& b) {
  const RobStatements& s = b.statements;
  for (int i = 0; i < b.link_count; ++i) {
    LinkDesc& link = b.robot.links[i];
    link.name = s.link_names.empty() ? "Link " + std::to_string(i) : s.link_names.values[i];
    link.parent = i - 1;
    if (!s.parents.empty()) {
      const int parent = static_cast<int>(s.parents.values[i]);
      if (parent < -1 || parent >= i) {
        b.Error(s.parents.lines[i], "parent of link " + std::to_string(i) +
                                        " must be -1 or a link index below " + std::to_string(i) +
                                        ", got " + std::to_string(parent));
      }
      link.parent = (parent < -1 || parent >= i) ? -1 : parent;
    }
    if (!s.joint_types.empty() && ToLower(s.joint_types.values[i]) == "p") {
      link.axis_type = LinkJointAxis::kPrismatic;
    }
  }
}

void BuildFrames(RobBuild& b) {
  const RobStatements& s = b.statements;
  for (int i = 0; i < b.link_count; ++i) {
    LinkDesc& link = b.robot.links[i];
    if (!s.tparent.empty()) {
      link.parent_transform = PoseFromKlamptNumbers(&s.tparent.values[12 * i]);
      if (!IsRotation(link.parent_transform.linear(), 1e-3)) {
        b.Warning(s.tparent.lines[12 * i], "'" + s.tparent.keyword + "' of link " +
                                               std::to_string(i) + " is not a rotation matrix");
      }
    } else {
      link.parent_transform =
          DenavitHartenberg(Angle(s.alpha, i), s.a.values[i], s.d.values[i], Angle(s.theta, i));
    }
    if (!s.axis.empty()) {
      link.axis = Triple(s.axis, i);
      if (link.axis.norm() == 0.0) {
        b.Error(s.axis.lines[3 * i],
                "'" + s.axis.keyword + "' of link " + std::to_string(i) + " is zero");
      }
    }
  }
  // `translation` and `rotation` place the root links
  Pose base = Pose::Identity();
  if (s.rotation) base.linear() = s.rotation->first;
  if (s.translation) base.translation() = s.translation->first;
  if (s.rotation && !IsRotation(s.rotation->first, 1e-3)) {
    b.Warning(s.rotation->second, "'rotation' is not a rotation matrix");
  }
  for (LinkDesc& link : b.robot.links) {
    if (link.parent < 0) link.parent_transform = base * link.parent_transform;
  }
}

// the line of value `i` of the first non-empty list, or 0
int LineOf(std::initializer_list<const NumberList*> lists, int i) {
  for (const NumberList* list : lists) {
    if (!list->empty()) return list->lines[i];
  }
  return 0;
}

void BuildLimits(RobBuild& b) {
  const RobStatements& s = b.statements;
  const auto set = [](const NumberList& list, int i, bool revolute, double* field) {
    if (!list.empty()) *field = LinkValue(list, i, revolute);
  };
  for (int i = 0; i < b.link_count; ++i) {
    LinkDesc& link = b.robot.links[i];
    const bool revolute = link.axis_type == LinkJointAxis::kRevolute;
    const std::string of_link = " of link " + std::to_string(i);
    set(s.q, i, revolute, &link.q_initial);
    if (!s.q.empty()) {
      b.CheckRow(s.q.lines[i], "'q'" + of_link + " (the initial config)", "config",
                 ElementKind::kRobot, {link.q_initial});
    }
    double q_min = link.q_min, q_max = link.q_max;
    set(s.q_min, i, revolute, &q_min);
    set(s.q_max, i, revolute, &q_max);
    if (b.CheckRow(LineOf({&s.q_min, &s.q_max}, i), "jointLimits" + of_link + " (qmin, qmax)",
                   "jointLimits", ElementKind::kLink, {q_min, q_max})) {
      link.q_min = q_min;
      link.q_max = q_max;
    }
    set(s.velocity_max, i, revolute, &link.velocity_max);
    link.velocity_min = -link.velocity_max;
    set(s.velocity_min, i, revolute, &link.velocity_min);
    set(s.acceleration_max, i, revolute, &link.acceleration_max);
    set(s.torque_max, i, revolute, &link.torque_max);
    set(s.power_max, i, revolute, &link.power_max);
  }
}

void BuildMass(RobBuild& b) {
  const RobStatements& s = b.statements;
  if (!s.inertia.empty() && !s.inertia_diag.empty()) {
    b.Error(s.inertia_diag.line, "'" + s.inertia_diag.keyword + "' and '" + s.inertia.keyword +
                                     "' are both given; use one of them");
  }
  for (int i = 0; i < b.link_count; ++i) {
    LinkDesc& link = b.robot.links[i];
    const std::string of_link = " of link " + std::to_string(i);
    if (!s.mass.empty() && b.CheckRow(s.mass.lines[i], "mass" + of_link, "mass", ElementKind::kLink,
                                      {s.mass.values[i]})) {
      link.mass = s.mass.values[i];
    }
    if (!s.com.empty() && b.CheckRow(s.com.lines[3 * i], "com" + of_link, "com", ElementKind::kLink,
                                     Values(s.com, i, 3))) {
      link.com = Triple(s.com, i);
    }
    ParamValue inertia;
    int line = 0;
    if (!s.inertia.empty()) {
      inertia = Values(s.inertia, i, 9);
      line = s.inertia.lines[9 * i];
    } else if (!s.inertia_diag.empty()) {
      const Vec3 diagonal = Triple(s.inertia_diag, i);
      inertia = {diagonal.x(), 0, 0, 0, diagonal.y(), 0, 0, 0, diagonal.z()};
      line = s.inertia_diag.lines[3 * i];
    }
    if (const auto lenient = LenientInertia(*FindParam("inertia", ElementKind::kLink), inertia)) {
      b.Warning(line, "inertia" + of_link + " " + lenient->warning);
      inertia = lenient->value;
    }
    if (!inertia.empty() &&
        b.CheckRow(line, "inertia" + of_link, "inertia", ElementKind::kLink, inertia)) {
      for (int k = 0; k < 9; ++k) link.inertia(k / 3, k % 3) = inertia[k];
    }
  }
}

}  // namespace

bool RobBuild::CheckRow(int line, const std::string& what, std::string_view key, ElementKind kind,
                        const ParamValue& value) const {
  const std::optional<std::string> refusal = RefuseRow(key, kind, value);
  if (refusal) Error(line, what + " " + *refusal);
  return !refusal;
}

int VoteLinkCount(const RobStatements& s, const std::string& path, Diagnostics& diagnostics) {
  const int n = Vote(s);
  const bool has_dh = !s.alpha.empty() && !s.a.empty() && !s.d.empty() && !s.theta.empty();
  if (n == 0 || (s.tparent.empty() && !has_dh)) {
    diagnostics.Error({path, 0, 0},
                      "no link frames: expected 'tparent' or all of 'alpha', 'a', 'd', 'theta'");
    return 0;
  }
  const int errors_before = diagnostics.error_count();
  const auto error = [&](int line, const std::string& message) {
    diagnostics.Error({path, line, 0}, message);
  };
  for (const PerLinkVector& vector : PerLinkVectors(s)) {
    const NumberList& list = *vector.list;
    if (!list.empty() && list.size() != n * vector.group) {
      error(list.line, Expected(list.keyword, n, vector.group, "value", list.size()));
    }
  }
  for (const WordList* list : {&s.link_names, &s.joint_types, &s.geometry_files}) {
    if (!list->empty() && list->size() != n) {
      const char* unit = list == &s.link_names       ? "name"
                         : list == &s.geometry_files ? "file name"
                                                     : "value";
      error(list->line, Expected(list->keyword, n, 1, unit, list->size()));
    }
  }
  for (const NumberList* list : {&s.geom_scale, &s.geom_margin}) {
    if (!list->empty() && list->size() != 1 && list->size() != n) {
      error(list->line, "'" + list->keyword + "' expects 1 or " + CountOf(n, "value") + ", got " +
                            std::to_string(list->size()));
    }
  }
  return diagnostics.error_count() == errors_before ? n : 0;
}

void BuildLinks(RobBuild& build) {
  build.robot.links.assign(build.link_count, LinkDesc());
  for (LinkDesc& link : build.robot.links) link.sim = DefaultLinkSimParams();
  BuildTree(build);
  BuildFrames(build);
  BuildLimits(build);
  BuildMass(build);
}

void LoadLinkGeometry(RobBuild& build) {
  const RobStatements& s = build.statements;
  const std::string directory = DirectoryOf(build.path);
  const auto per_link = [](const NumberList& list, int i, double fallback) {
    if (list.empty()) return fallback;
    return list.size() == 1 ? list.values[0] : list.values[i];
  };
  for (int i = 0; i < build.link_count && !s.geometry_files.empty(); ++i) {
    const std::string& file = s.geometry_files.values[i];
    if (file.empty()) continue;
    GeometryDesc geometry;
    if (!LoadGeometryFile(ResolvePath(directory, file), build.At(s.geometry_files.line),
                          build.context, &geometry)) {
      continue;
    }
    const double scale = per_link(s.geom_scale, i, 1.0);
    if (scale == 0.0) {
      build.Error(s.geom_scale.line,
                  "'" + s.geom_scale.keyword + "' of link " + std::to_string(i) + " must not be 0");
    }
    geometry.scale = Vec3::Constant(scale);
    geometry.margin = per_link(s.geom_margin, i, 0.0);
    build.robot.links[i].geometry = {geometry};
  }
  // geomtransforms apply after the scale, each after the previous one
  for (const GeomTransformStatement& entry : s.geom_transforms) {
    if (entry.link < 0 || entry.link >= build.link_count) {
      build.Error(entry.line, OutOfRangeMessage("geomtransform", entry.link, build.link_count));
    } else if (build.robot.links[entry.link].geometry.empty()) {
      build.Warning(entry.line, "'geomtransform' of link " + std::to_string(entry.link) +
                                    ", which has no geometry, is ignored");
    } else {
      GeometryDesc& geometry = build.robot.links[entry.link].geometry.front();
      geometry.transform = entry.matrix * geometry.transform;
    }
  }
}

void ApplyAutotorque(RobBuild& build) {
  const double autotorque = build.statements.autotorque;
  if (autotorque == 0.0) return;
  // Klamp't's heuristic, treating the links as one serial chain from the last link back
  const double gravity = std::abs(autotorque) * 9.8;
  double mass_below = 0.0, com_distance = 0.0;
  for (int i = build.link_count - 1; i >= 0; --i) {
    LinkDesc& link = build.robot.links[i];
    const double previous_mass = mass_below;
    const double previous_distance = com_distance + link.parent_transform.translation().norm();
    mass_below += link.mass;
    const double total = link.mass + previous_mass;
    com_distance = total > 0.0
                       ? (link.com.norm() * link.mass + previous_distance * previous_mass) / total
                       : 0.0;
    link.torque_max = com_distance * mass_below * gravity;
  }
}

}  // namespace lamina::core::rob
