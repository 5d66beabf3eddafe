// SPDX-License-Identifier: MIT
// The MuJoCo peer: the peer world as MJCF, loaded from memory and stepped with MuJoCo's defaults
// (semi-implicit Euler, Newton solver, pyramidal cone, soft contacts with solref 0.02 s and
// damping ratio 1). Bodies joined by hinges are nested (MuJoCo's joints are generalized
// coordinates, so a hinge has no gap); every other body has a free joint. Only the peer world's
// pairs collide, each an explicit <pair> with Lamina's blended friction; a pair with restitution
// e > 0 gets the damping ratio ζ = −ln e / √(π² + ln² e) of a spring–damper that rebounds with e
// (MuJoCo has no restitution coefficient).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>

#include <mujoco/mujoco.h>

#include "core/number_text.h"
#include "tests/bench/peers/peer_run.h"

namespace lamina::peers {
namespace {

// MJCF numbers: the shortest text that reads back to the same double (core/number_text.h)
std::string Vec(const Vec3& v) {
  return core::FormatDoubles(v.data(), 3);
}

std::string Quat(const Mat3& rotation) {
  const Eigen::Quaterniond q(rotation);
  const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
  return core::FormatDoubles(wxyz, 4);
}

std::string Num(double value) {
  return core::FormatDouble(value);
}

std::string GeomName(int body, std::size_t shape) {
  return "g" + std::to_string(body) + "_" + std::to_string(shape);
}

std::string Geom(const PeerShape& shape, const std::string& name) {
  const std::string type = shape.kind == PeerShape::Kind::kBox ? "box" : "sphere";
  const Vec3 size =
      shape.kind == PeerShape::Kind::kBox ? shape.half_size : Vec3(shape.radius, 0, 0);
  return "<geom name=\"" + name + "\" type=\"" + type + "\" size=\"" + Vec(size) + "\" pos=\"" +
         Vec(shape.pose.translation()) + "\" quat=\"" + Quat(shape.pose.linear()) +
         "\" contype=\"0\" conaffinity=\"0\" mass=\"0\"/>\n";
}

std::string Inertial(const PeerBody& body) {
  const Mat3& I = body.inertia;
  return "<inertial pos=\"" + Vec(body.com) + "\" mass=\"" + Num(body.mass) + "\" fullinertia=\"" +
         Num(I(0, 0)) + " " + Num(I(1, 1)) + " " + Num(I(2, 2)) + " " + Num(I(0, 1)) + " " +
         Num(I(0, 2)) + " " + Num(I(1, 2)) + "\"/>\n";
}

class MujocoModelWriter {
 public:
  explicit MujocoModelWriter(const PeerWorld& world) : world_(world) {}

  std::string Write(double step) {
    std::string xml = "<mujoco model=\"lamina-peer\">\n<option timestep=\"" + Num(step) +
                      "\" gravity=\"" + Vec(world_.gravity) + "\"/>\n" +
                      "<size njmax=\"4000\" nconmax=\"1000\"/>\n<worldbody>\n";
    for (std::size_t b = 0; b < world_.bodies.size(); ++b) {
      const PeerBody& body = world_.bodies[b];
      if (!body.dynamic) xml += Shapes(static_cast<int>(b));
    }
    for (std::size_t b = 0; b < world_.bodies.size(); ++b) {
      if (world_.bodies[b].dynamic && Parent(static_cast<int>(b)) == -1)
        xml += Body(static_cast<int>(b), Pose::Identity());
    }
    return xml + "</worldbody>\n<contact>\n" + Pairs() + "</contact>\n</mujoco>\n";
  }

  /// The hinge holding body `b`, or nullptr.
  const PeerHinge* HingeOf(int b) const {
    for (const PeerHinge& hinge : world_.hinges) {
      if (hinge.body == b) return &hinge;
    }
    return nullptr;
  }

 private:
  int Parent(int b) const {
    const PeerHinge* hinge = HingeOf(b);
    return hinge == nullptr ? -1 : hinge->parent;
  }

  std::string Shapes(int b) const {
    std::string xml;
    const PeerBody& body = world_.bodies[b];
    for (std::size_t s = 0; s < body.shapes.size(); ++s) {
      xml += Geom(body.shapes[s], GeomName(b, s));
    }
    return xml;
  }

  std::string Joint(int b) const {
    const PeerHinge* hinge = HingeOf(b);
    if (hinge == nullptr) return "<freejoint/>\n";
    const Pose& pose = world_.bodies[b].pose;
    return "<joint type=\"hinge\" pos=\"" + Vec(pose.inverse() * hinge->point) + "\" axis=\"" +
           Vec(pose.linear().transpose() * hinge->axis) + "\" damping=\"0\" armature=\"0\"/>\n";
  }

  // Body `b` nested in the body whose frame is `parent` (world frame), and its children.
  std::string Body(int b, const Pose& parent) const {
    const PeerBody& body = world_.bodies[b];
    const Pose local = parent.inverse() * body.pose;
    std::string xml = "<body name=\"b" + std::to_string(b) + "\" pos=\"" +
                      Vec(local.translation()) + "\" quat=\"" + Quat(local.linear()) + "\">\n";
    xml += Joint(b) + Inertial(body) + Shapes(b);
    for (std::size_t c = 0; c < world_.bodies.size(); ++c) {
      if (Parent(static_cast<int>(c)) == b) xml += Body(static_cast<int>(c), body.pose);
    }
    return xml + "</body>\n";
  }

  std::string Pairs() const {
    std::string xml;
    for (const PeerPair& pair : world_.pairs) {
      for (std::size_t i = 0; i < world_.bodies[pair.a].shapes.size(); ++i) {
        for (std::size_t j = 0; j < world_.bodies[pair.b].shapes.size(); ++j) {
          xml += "<pair geom1=\"" + GeomName(pair.a, i) + "\" geom2=\"" + GeomName(pair.b, j) +
                 "\" condim=\"3\" friction=\"" + Num(pair.friction) + " " + Num(pair.friction) +
                 " 0.005 0.0001 0.0001\"" + SolRef(pair.restitution) + "/>\n";
        }
      }
    }
    return xml;
  }

  // e = 1 would need ζ = 0, which MuJoCo refuses (it falls back to its default solref): ζ stays
  // at least 1e-6, a rebound of e = 0.999997
  static std::string SolRef(double restitution) {
    if (restitution <= 0.0) return "";
    const double log_e = std::log(restitution);
    const double zeta = std::max(1e-6, -log_e / std::sqrt(M_PI * M_PI + log_e * log_e));
    return " solref=\"0.02 " + Num(zeta) + "\"";
  }

  const PeerWorld& world_;
};

std::mutex load_mutex;  // MuJoCo's XML parser is not documented as thread-safe

// MuJoCo's warnings would go to the terminal and to MUJOCO_LOG.TXT in the working folder; the
// run reads the one that matters from mjData (MujocoPeer::Trouble) instead.
void QuietWarning(const char*) {}

mjModel* LoadFromMemory(const std::string& xml, std::string* why) {
  const std::lock_guard<std::mutex> lock(load_mutex);
  mju_user_warning = QuietWarning;
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  mj_makeEmptyFileVFS(vfs.get(), "peer.xml", static_cast<int>(xml.size()));
  const int file = mj_findFileVFS(vfs.get(), "peer.xml");
  std::memcpy(vfs->filedata[file], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* model = mj_loadXML("peer.xml", vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (model == nullptr) *why = std::string("MuJoCo refused the model: ") + error;
  return model;
}

class MujocoPeer : public PeerEngine {
 public:
  ~MujocoPeer() override {
    if (data_ != nullptr) mj_deleteData(data_);
    if (model_ != nullptr) mj_deleteModel(model_);
  }

  bool Build(const PeerWorld& world, double step, std::string* why) override {
    for (const PeerPair& pair : world.pairs) {
      if (pair.restitution >= 1.0) {
        *why =
            "restitution 1: MuJoCo's contacts are spring-dampers, and one without damping "
            "(damping ratio 0) is refused";
        return false;
      }
    }
    MujocoModelWriter writer(world);
    model_ = LoadFromMemory(writer.Write(step), why);
    if (model_ == nullptr) return false;
    data_ = mj_makeData(model_);
    for (std::size_t b = 0; b < world.bodies.size(); ++b) {
      if (!world.bodies[b].dynamic) continue;
      objects_.push_back(mj_name2id(model_, mjOBJ_BODY, ("b" + std::to_string(b)).c_str()));
      SetVelocity(world.bodies[b], writer.HingeOf(static_cast<int>(b)), objects_.back());
    }
    mj_forward(model_, data_);
    return true;
  }

  void Step() override { mj_step(model_, data_); }

  std::string Trouble() const override {
    if (data_->warning[mjWARN_BADQACC].number == 0) return "";
    return "MuJoCo found bad accelerations at t = " + Num(data_->time) +
           " s and reset the simulation";
  }

  void Read(PeerReadout* readout) override {
    mj_kinematics(model_, data_);
    mj_comPos(model_, data_);
    mj_comVel(model_, data_);
    mj_collision(model_, data_);
    readout->objects.resize(objects_.size());
    for (std::size_t i = 0; i < objects_.size(); ++i) ReadBody(objects_[i], &readout->objects[i]);
    readout->contacts = data_->ncon;
    readout->deepest = 0.0;
    for (int c = 0; c < data_->ncon; ++c)
      readout->deepest = std::max(readout->deepest, -data_->contact[c].dist);
  }

 private:
  // A free joint's velocity is the frame origin's (world) and the angular velocity in the body's
  // axes; a hinge's is the rate about its axis.
  void SetVelocity(const PeerBody& body, const PeerHinge* hinge, int id) {
    const int joint = model_->body_jntadr[id];
    const int dof = model_->jnt_dofadr[joint];
    if (hinge != nullptr) {
      data_->qvel[dof] = body.velocity.angular.dot(hinge->axis);
      return;
    }
    const Vec3 local = body.pose.linear().transpose() * body.velocity.angular;
    for (int k = 0; k < 3; ++k) {
      data_->qvel[dof + k] = body.velocity.linear[k];
      data_->qvel[dof + 3 + k] = local[k];
    }
  }

  void ReadBody(int id, PeerState* state) const {
    const mjtNum* p = data_->xpos + 3 * id;
    const mjtNum* q = data_->xquat + 4 * id;
    state->pose = Pose::Identity();
    state->pose.translation() = Vec3(p[0], p[1], p[2]);
    state->pose.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
    mjtNum velocity[6];
    mj_objectVelocity(model_, data_, mjOBJ_XBODY, id, velocity, 0);
    state->velocity.angular = Vec3(velocity[0], velocity[1], velocity[2]);
    state->velocity.linear = Vec3(velocity[3], velocity[4], velocity[5]);
  }

  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  std::vector<int> objects_;  ///< MuJoCo body id of each object
};

}  // namespace

std::unique_ptr<PeerEngine> MakeMujocoPeer() {
  return std::make_unique<MujocoPeer>();
}

}  // namespace lamina::peers
