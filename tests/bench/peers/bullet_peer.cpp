// SPDX-License-Identifier: MIT
// The Bullet peer (double precision): a btDiscreteDynamicsWorld with the sequential-impulse
// solver at the run's iterations and Bullet's other defaults (ERP 0.2 and warm starting 0.85;
// split impulse only for penetrations deeper than 4 cm, so a shallower overlap is pushed out
// through the velocity, which adds to a bounce). A body's Bullet frame is its centre of mass on
// its principal axes; hinges are btHingeConstraints (maximal coordinates, like ODE's). Each
// contact point gets its pair's blended friction and restitution through Bullet's contact-added
// callback, and contacts closing slower than the world's bounce threshold do not bounce (Bullet's
// restitution velocity threshold), as in Lamina.
#include <cmath>
#include <map>
#include <memory>
#include <utility>

#include <Eigen/Eigenvalues>
#include <btBulletDynamicsCommon.h>

#include "tests/bench/peers/peer_run.h"

namespace lamina::peers {
namespace {

btVector3 Bt(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}
Vec3 FromBt(const btVector3& v) {
  return {v.x(), v.y(), v.z()};
}

btTransform Bt(const Pose& pose) {
  const Mat3& r = pose.linear();
  const btMatrix3x3 basis(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1),
                          r(2, 2));
  return btTransform(basis, Bt(Vec3(pose.translation())));
}

Pose FromBt(const btTransform& transform) {
  Pose pose = Pose::Identity();
  const btMatrix3x3& b = transform.getBasis();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) pose.linear()(i, j) = b[i][j];
  }
  pose.translation() = FromBt(transform.getOrigin());
  return pose;
}

// The centre-of-mass frame on the principal axes, in the body frame, and the principal moments.
std::pair<Pose, Vec3> PrincipalFrame(const PeerBody& body) {
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(body.inertia);
  Mat3 axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  Pose frame = Pose::Identity();
  frame.linear() = axes;
  frame.translation() = body.com;
  return {frame, solver.eigenvalues()};
}

// The blended surface of each touching pair, by the two bodies' indices.
using PairTable = std::map<std::pair<int, int>, const PeerPair*>;

bool ContactAdded(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                  const btCollisionObjectWrapper* b, int, int) {
  const auto* table = static_cast<const PairTable*>(a->getCollisionObject()->getUserPointer());
  const int ia = a->getCollisionObject()->getUserIndex();
  const int ib = b->getCollisionObject()->getUserIndex();
  const auto found = table->find({std::min(ia, ib), std::max(ia, ib)});
  if (found != table->end()) {
    point.m_combinedFriction = found->second->friction;
    point.m_combinedRestitution = found->second->restitution;
  }
  return true;
}

class BulletPeer : public PeerEngine {
 public:
  explicit BulletPeer(int iterations) : iterations_(iterations) {}
  ~BulletPeer() override {
    if (world_ == nullptr) return;
    for (int i = world_->getNumConstraints() - 1; i >= 0; --i)
      world_->removeConstraint(world_->getConstraint(i));
    for (auto& body : bodies_) world_->removeRigidBody(body.get());
  }

  bool Build(const PeerWorld& world, double step, std::string* why) override {
    (void)why;
    step_ = step;
    MakeWorld(world);
    for (const PeerPair& pair : world.pairs)
      pairs_[{std::min(pair.a, pair.b), std::max(pair.a, pair.b)}] = &pair;
    for (std::size_t b = 0; b < world.bodies.size(); ++b)
      AddBody(world.bodies[b], static_cast<int>(b));
    for (const PeerHinge& hinge : world.hinges) AddHinge(hinge);
    return true;
  }

  void Step() override { world_->stepSimulation(step_, 0, step_); }

  void Read(PeerReadout* readout) override {
    world_->performDiscreteCollisionDetection();
    readout->objects.clear();
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (offsets_[b].second) readout->objects.push_back(State(static_cast<int>(b)));
    }
    readout->contacts = 0;
    readout->deepest = 0.0;
    btDispatcher* dispatcher = world_->getDispatcher();
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      for (int c = 0; c < manifold->getNumContacts(); ++c) {
        ++readout->contacts;
        readout->deepest = std::max(readout->deepest, -manifold->getContactPoint(c).getDistance());
      }
    }
  }

 private:
  void MakeWorld(const PeerWorld& world) {
    configuration_ = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(configuration_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                       solver_.get(), configuration_.get());
    world_->setGravity(Bt(world.gravity));
    world_->getSolverInfo().m_numIterations = iterations_;
    world_->getSolverInfo().m_restitutionVelocityThreshold = world.bounce_velocity_threshold;
    gContactAddedCallback = ContactAdded;
  }

  std::unique_ptr<btCollisionShape> Shape(const PeerShape& shape) {
    if (shape.kind == PeerShape::Kind::kSphere)
      return std::make_unique<btSphereShape>(shape.radius);
    return std::make_unique<btBoxShape>(Bt(shape.half_size));
  }

  // The body's one shape where it sits at the COM frame `offset`, else a compound of them all
  // (which Bullet collides more slowly).
  btCollisionShape* Collider(const PeerBody& body, const Pose& offset) {
    if (body.shapes.size() == 1 &&
        (offset.inverse() * body.shapes[0].pose).matrix().isIdentity(1e-12)) {
      shapes_.push_back(Shape(body.shapes[0]));
      return shapes_.back().get();
    }
    auto compound = std::make_unique<btCompoundShape>();
    for (const PeerShape& shape : body.shapes) {
      shapes_.push_back(Shape(shape));
      compound->addChildShape(Bt(Pose(offset.inverse() * shape.pose)), shapes_.back().get());
    }
    shapes_.push_back(std::move(compound));
    return shapes_.back().get();
  }

  // Body `b`: Bullet's frame is the COM frame `offset` (body frame) for a dynamic body.
  void AddBody(const PeerBody& body, int b) {
    const auto [offset, moments] =
        body.dynamic ? PrincipalFrame(body) : std::pair<Pose, Vec3>(Pose::Identity(), Vec3::Zero());
    btRigidBody::btRigidBodyConstructionInfo info(body.dynamic ? body.mass : 0.0, nullptr,
                                                  Collider(body, offset), Bt(moments));
    info.m_startWorldTransform = Bt(Pose(body.pose * offset));
    auto rigid = std::make_unique<btRigidBody>(info);
    rigid->setUserIndex(b);
    rigid->setUserPointer(&pairs_);
    rigid->setCollisionFlags(rigid->getCollisionFlags() |
                             btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
    rigid->setActivationState(DISABLE_DEACTIVATION);
    rigid->setSleepingThresholds(0, 0);
    const Vec3 com = body.pose * body.com;
    rigid->setLinearVelocity(Bt(
        Vec3(body.velocity.linear + body.velocity.angular.cross(com - body.pose.translation()))));
    rigid->setAngularVelocity(Bt(body.velocity.angular));
    world_->addRigidBody(rigid.get());
    offsets_.push_back({offset, body.dynamic});
    bodies_.push_back(std::move(rigid));
  }

  void AddHinge(const PeerHinge& hinge) {
    btRigidBody& body = *bodies_[hinge.body];
    const btTransform to_body = body.getWorldTransform().inverse();
    const btVector3 pivot = to_body * Bt(hinge.point);
    const btVector3 axis = to_body.getBasis() * Bt(hinge.axis);
    std::unique_ptr<btHingeConstraint> constraint;
    if (hinge.parent < 0) {
      constraint = std::make_unique<btHingeConstraint>(body, pivot, axis);
    } else {
      btRigidBody& parent = *bodies_[hinge.parent];
      const btTransform to_parent = parent.getWorldTransform().inverse();
      constraint =
          std::make_unique<btHingeConstraint>(body, parent, pivot, to_parent * Bt(hinge.point),
                                              axis, to_parent.getBasis() * Bt(hinge.axis));
    }
    world_->addConstraint(constraint.get(), true);
    constraints_.push_back(std::move(constraint));
  }

  PeerState State(int b) const {
    const btRigidBody& body = *bodies_[b];
    PeerState state;
    state.pose = FromBt(body.getWorldTransform()) * offsets_[b].first.inverse();
    const Vec3 omega = FromBt(body.getAngularVelocity());
    const Vec3 com = FromBt(body.getWorldTransform().getOrigin());
    state.velocity.angular = omega;
    state.velocity.linear =
        FromBt(body.getLinearVelocity()) + omega.cross(state.pose.translation() - com);
    return state;
  }

  int iterations_;
  double step_ = 0.001;
  std::unique_ptr<btDefaultCollisionConfiguration> configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<std::unique_ptr<btTypedConstraint>> constraints_;
  std::vector<std::pair<Pose, bool>> offsets_;  ///< COM frame in the body frame; dynamic
  PairTable pairs_;
};

}  // namespace

std::unique_ptr<PeerEngine> MakeBulletPeer(int iterations) {
  return std::make_unique<BulletPeer>(iterations);
}

std::unique_ptr<PeerEngine> MakeMujocoPeer();

std::unique_ptr<PeerEngine> MakePeerEngine(const core::AccuracySolver& solver) {
  if (solver.peer == "mujoco") return MakeMujocoPeer();
  if (solver.peer == "bullet") return MakeBulletPeer(solver.iterations);
  return nullptr;
}

}  // namespace lamina::peers
