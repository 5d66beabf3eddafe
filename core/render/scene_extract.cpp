// SPDX-License-Identifier: MIT
// Builds the RenderScene of a world at given poses: body meshes first, then the overlays sized
// to the scene.
#include "core/render/scene_extract.h"

#include <algorithm>
#include <array>
#include <utility>

#include "core/robot/kinematics.h"

namespace lamina::core {

namespace {

const Rgba kContactColor(1.0f, 0.9f, 0.1f, 1.0f);
const Rgba kPenetratingColor(1.0f, 0.15f, 0.1f, 1.0f);
const Rgba kForceColor(1.0f, 0.5f, 0.05f, 1.0f);
const Rgba kComColor(0.9f, 0.1f, 0.9f, 1.0f);
const Rgba kJointColor(1.0f, 0.6f, 0.1f, 1.0f);
const Rgba kBodyBoxColor(0.9f, 0.15f, 0.15f, 1.0f);
const Rgba kTerrainBoxColor(1.0f, 0.6f, 0.1f, 1.0f);
const Rgba kSelectedBoxColor(1.0f, 0.85f, 0.2f, 1.0f);
constexpr float kPaddingAlpha = 0.35f;

// one drawn piece of a body: a geometry at a pose
struct BodyPart {
  const GeometryDesc* geometry;
  Pose pose;
  Rgba color;
  int world_id;
  bool terrain;
  bool selected;
  double padding;
};

// one body's frame and centre of mass, for the frame and COM overlays
struct ExtractedFrame {
  Pose pose;
  Vec3 com_world;
};

Eigen::AlignedBox3d TransformedBox(const Eigen::AlignedBox3f& box, const Eigen::Matrix4f& m) {
  Eigen::AlignedBox3d out;
  if (box.isEmpty()) return out;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3f p = box.corner(static_cast<Eigen::AlignedBox3f::CornerType>(corner));
    out.extend((m * p.homogeneous()).head<3>().cast<double>());
  }
  return out;
}

bool IsPlane(const GeometryDesc& geometry) {
  return geometry.kind == GeometryKind::kPrimitive &&
         geometry.primitive.type == PrimitiveType::kPlane;
}

void AddTerrainParts(const WorldDesc& world, int selected_id, std::vector<BodyPart>* parts) {
  for (size_t i = 0; i < world.terrains.size(); ++i) {
    const TerrainDesc& terrain = world.terrains[i];
    const int id = world.TerrainId(static_cast<int>(i));
    parts->push_back({&terrain.geometry, Pose::Identity(),
                      DisplayColor(terrain.display).value_or(DefaultTerrainColor()), id, true,
                      id == selected_id, terrain.sim.padding + terrain.geometry.margin});
  }
}

void AddObjectParts(const WorldDesc& world, const WorldPoses& poses, int selected_id,
                    std::vector<BodyPart>* parts, std::vector<ExtractedFrame>* frames) {
  for (size_t i = 0; i < world.objects.size(); ++i) {
    const RigidObjectDesc& object = world.objects[i];
    const int id = world.ObjectId(static_cast<int>(i));
    const Pose pose = DrawnObjectPose(world, poses, static_cast<int>(i));
    parts->push_back({&object.geometry, pose,
                      DisplayColor(object.display).value_or(DefaultObjectColor()), id, false,
                      id == selected_id, object.sim.padding + object.geometry.margin});
    frames->push_back({pose, pose * object.com});
  }
}

void AddRobotParts(const WorldDesc& world, const WorldPoses& poses, int robot_index,
                   int selected_id, std::vector<BodyPart>* parts,
                   std::vector<ExtractedFrame>* frames) {
  const RobotDesc& robot = world.robots[robot_index];
  const bool robot_selected = world.RobotId(robot_index) == selected_id;
  const std::vector<Pose> link_frames =
      LinkTransforms(robot, DrawnRobotConfiguration(world, poses, robot_index));
  const std::vector<Vec3> coms = LinkComPositions(robot, link_frames);
  for (int l = 0; l < robot.dof(); ++l) {
    const LinkDesc& link = robot.links[l];
    const int id = world.RobotLinkId(robot_index, l);
    for (const GeometryDesc& geometry : link.geometry) {
      parts->push_back({&geometry, link_frames[l], RobotLinkColor(robot, l), id, false,
                        robot_selected || id == selected_id, link.sim.padding + geometry.margin});
    }
    if (link.has_geometry()) frames->push_back({link_frames[l], coms[l]});
  }
}

// every body's pieces at `poses`, in world id order
std::vector<BodyPart> CollectParts(const WorldDesc& world, const WorldPoses& poses, int selected_id,
                                   std::vector<ExtractedFrame>* frames) {
  std::vector<BodyPart> parts;
  AddTerrainParts(world, selected_id, &parts);
  AddObjectParts(world, poses, selected_id, &parts, frames);
  for (size_t r = 0; r < world.robots.size(); ++r)
    AddRobotParts(world, poses, static_cast<int>(r), selected_id, &parts, frames);
  return parts;
}

void AddBoxLines(const Eigen::AlignedBox3f& box, const Eigen::Matrix4f& m, const Rgba& color,
                 RenderScene* scene) {
  std::array<Eigen::Vector3f, 8> c;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3f local((i & 1) ? box.max().x() : box.min().x(),
                                (i & 2) ? box.max().y() : box.min().y(),
                                (i & 4) ? box.max().z() : box.min().z());
    c[i] = (m * local.homogeneous()).head<3>();
  }
  for (int i = 0; i < 8; ++i) {
    for (int bit : {1, 2, 4}) {
      if (!(i & bit)) scene->lines.push_back({c[i], c[i | bit], color});
    }
  }
}

void AddArrow(const Vec3& from, const Vec3& to, float radius, const Rgba& color,
              RenderScene* scene) {
  if ((to - from).norm() < 1e-6) return;
  scene->arrows.push_back({from.cast<float>(), to.cast<float>(), radius, color});
}

// a size for markers: a fraction of the scene, clamped to sensible millimetres
float MarkerSize(const RenderScene& scene) {
  const Eigen::AlignedBox3d& box = scene.body_bounds.isEmpty() ? scene.bounds : scene.body_bounds;
  const double diagonal = box.isEmpty() ? 1.0 : box.diagonal().norm();
  return static_cast<float>(std::clamp(0.006 * diagonal, 0.002, 0.03));
}

void AddBodyItem(const BodyPart& part, std::shared_ptr<const RenderMesh> mesh, const Rgba& color,
                 RenderScene* scene) {
  DrawItem item;
  item.mesh = std::move(mesh);
  item.transform = (part.pose * part.geometry->Matrix()).matrix().cast<float>();
  item.color = color;
  item.world_id = part.world_id;
  item.flags = kDrawNone;
  if (part.terrain) item.flags |= kDrawTerrain;
  if (part.selected) item.flags |= kDrawSelected;
  if (item.color.w() < 1.0f) item.flags |= kDrawTranslucent;
  scene->items.push_back(item);
  if (IsPlane(*part.geometry)) return;
  const Eigen::AlignedBox3d box = TransformedBox(item.mesh->bounds, item.transform);
  scene->bounds.extend(box);
  if (!part.terrain) scene->body_bounds.extend(box);
}

// a point cloud with colours: one item per colour group, in the file's colours (the body's
// alpha kept)
bool AddColoredBody(const BodyPart& part, RenderMeshCache* cache, RenderScene* scene) {
  const std::vector<ColoredShape>& shapes = cache->ColoredShapes(*part.geometry);
  for (const ColoredShape& shape : shapes) {
    AddBodyItem(part, shape.mesh,
                Rgba(shape.color.x(), shape.color.y(), shape.color.z(), part.color.w()), scene);
  }
  return !shapes.empty();
}

void AddBodies(const std::vector<BodyPart>& parts, RenderMeshCache* cache, RenderScene* scene) {
  for (const BodyPart& part : parts) {
    if (AddColoredBody(part, cache, scene)) continue;
    std::shared_ptr<const RenderMesh> mesh = cache->Shape(*part.geometry);
    if (mesh) AddBodyItem(part, std::move(mesh), part.color, scene);
  }
}

void AddPaddingLayer(const std::vector<BodyPart>& parts, RenderMeshCache* cache,
                     RenderScene* scene) {
  for (const BodyPart& part : parts) {
    if (part.padding <= 0.0 || IsPlane(*part.geometry)) continue;
    std::shared_ptr<const RenderMesh> mesh = cache->PaddedShape(*part.geometry, part.padding);
    if (!mesh) continue;
    DrawItem item;
    item.mesh = mesh;
    item.transform = part.pose.matrix().cast<float>();
    const Rgba base = part.color;
    item.color =
        Rgba(0.5f + 0.5f * base.x(), 0.5f + 0.5f * base.y(), 0.5f + 0.5f * base.z(), kPaddingAlpha);
    item.world_id = part.world_id;
    item.flags = kDrawTranslucent;
    scene->items.push_back(item);
  }
}

void AddBoxes(const OverlayOptions& options, RenderScene* scene) {
  const size_t body_items = scene->items.size();
  for (size_t i = 0; i < body_items; ++i) {
    const DrawItem& item = scene->items[i];
    if (item.has(kDrawTranslucent) && !item.has(kDrawSelected)) continue;
    // a selected body gets a highlight box (a selected robot only its tint: one box per link
    // would hide it)
    if (item.has(kDrawSelected) && item.world_id == options.selected_id) {
      AddBoxLines(item.mesh->bounds, item.transform, kSelectedBoxColor, scene);
    } else if (options.bbox) {
      AddBoxLines(item.mesh->bounds, item.transform,
                  item.has(kDrawTerrain) ? kTerrainBoxColor : kBodyBoxColor, scene);
    }
  }
}

void AddFrames(const OverlayOptions& options, const std::vector<ExtractedFrame>& frames,
               float marker, RenderScene* scene) {
  const double axis_length = std::max(10.0 * marker, 0.03);
  for (const ExtractedFrame& frame : frames) {
    if (options.com)
      scene->points.push_back({frame.com_world.cast<float>(), 1.6f * marker, kComColor});
    if (!options.frames) continue;
    const Vec3 origin = frame.pose.translation();
    for (int axis = 0; axis < 3; ++axis) {
      Rgba color(0.1f, 0.1f, 0.1f, 1.0f);
      color[axis] = 0.95f;
      AddArrow(origin, origin + axis_length * frame.pose.linear().col(axis), 0.25f * marker, color,
               scene);
    }
  }
}

void AddContacts(const OverlayOptions& options, const std::vector<ContactMarker>& contacts,
                 float marker, RenderScene* scene) {
  for (const ContactMarker& contact : contacts) {
    if (options.contacts) {
      scene->points.push_back({contact.position.cast<float>(), marker,
                               contact.penetrating ? kPenetratingColor : kContactColor});
    }
    if (options.normals) {
      AddArrow(contact.position, contact.position + options.normal_length * contact.normal,
               0.25f * marker, kContactColor, scene);
    }
    if (options.forces) {
      AddArrow(contact.position, contact.position + options.force_scale * contact.force,
               0.35f * marker, kForceColor, scene);
    }
  }
}

// world id of a joint's body (-1: a terrain, which does not move)
int JointBodyId(const WorldDesc& world, const WorldJointBody& body) {
  if (body.kind == WorldId::Kind::kRigidObject) return world.ObjectId(body.index);
  if (body.kind == WorldId::Kind::kRobotLink) return world.RobotLinkId(body.index, body.link);
  return -1;
}

// each world joint where it is now, at its first moving body (the world when it holds only
// terrains): a hinge as its axis level with the body's centre of mass, a slider as its direction
// through it, a fixed joint as a point there. `initial` gives the frame the joint was made at.
void AddJoints(const WorldDesc& world, const WorldPoses& poses, float marker, RenderScene* scene) {
  const WorldPoses initial = InitialPoses(world);
  const double length = std::max(40.0 * marker, 0.1);
  for (const WorldJointDesc& joint : world.joints) {
    Pose motion = Pose::Identity();  // how the first moving body moved from its initial pose
    std::optional<Vec3> centre;
    for (const WorldJointBody& body : joint.bodies) {
      const int id = JointBodyId(world, body);
      const std::optional<Pose> now = id >= 0 ? DrawnBodyFrame(world, poses, id) : std::nullopt;
      const std::optional<Pose> start = id >= 0 ? DrawnBodyFrame(world, initial, id) : std::nullopt;
      if (!now || !start) continue;
      motion = *now * start->inverse();
      const bool object = body.kind == WorldId::Kind::kRigidObject;
      centre = *now * (object ? world.objects[body.index].com
                              : world.robots[body.index].links[body.link].com);
      break;
    }
    const Vec3 axis = motion.linear() * joint.axis;
    Vec3 at = centre ? *centre : motion * joint.point;
    if (joint.type == WorldJointType::kHinge) {
      const Vec3 point = motion * joint.point;
      at = point + axis * axis.dot(at - point);
    }
    scene->points.push_back({at.cast<float>(), 2.0f * marker, kJointColor});
    if (joint.type == WorldJointType::kFixed) continue;
    AddArrow(at - 0.5 * length * axis, at + 0.5 * length * axis, 0.35f * marker, kJointColor,
             scene);
  }
}

}  // namespace

void ExtractScene(const WorldDesc& world, const WorldPoses& poses, const OverlayOptions& options,
                  const std::vector<ContactMarker>& contacts, RenderMeshCache* cache,
                  RenderScene* scene) {
  *scene = RenderScene();
  std::vector<ExtractedFrame> frames;
  const std::vector<BodyPart> parts = CollectParts(world, poses, options.selected_id, &frames);
  AddBodies(parts, cache, scene);
  const float marker = MarkerSize(*scene);
  AddBoxes(options, scene);
  if (options.padding) AddPaddingLayer(parts, cache, scene);
  AddFrames(options, frames, marker, scene);
  AddContacts(options, contacts, marker, scene);
  if (options.joints) AddJoints(world, poses, marker, scene);
}

}  // namespace lamina::core
