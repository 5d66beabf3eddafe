// SPDX-License-Identifier: MIT
// The raw ODE box stack (see raw_ode_stack.h).
#include "tests/bench/raw_ode_stack.h"

#include <algorithm>
#include <cmath>

#include "core/sim/ode_handle.h"
#include "tests/bench/bench_support.h"

namespace lamina::bench {

RawOdeBoxStack::RawOdeBoxStack(const core::SimSettings& settings) : settings_(settings) {
  // the same ODE set-up as Lamina's simulator (thread data, error handlers)
  core::EnsureOdeInitialized();
  world_ = dWorldCreate();
  space_ = dSimpleSpaceCreate(nullptr);
  contact_group_ = dJointGroupCreate(0);
  dWorldSetERP(world_, settings_.erp);
  dWorldSetCFM(world_, settings_.cfm);
  dWorldSetAutoDisableFlag(world_, 0);
  dWorldSetGravity(world_, settings_.gravity.x(), settings_.gravity.y(), settings_.gravity.z());

  // the slab: a static geom (no body) whose top face is z = 0
  dGeomID slab = dCreateBox(space_, kStackSlabSize.x(), kStackSlabSize.y(), kStackSlabSize.z());
  dGeomSetPosition(slab, 0, 0, -kStackSlabSize.z() / 2);

  for (int i = 0; i < kStackBoxCount; ++i) {
    dBodyID body = dBodyCreate(world_);
    // Lamina integrates orientations the same way
    dBodySetFiniteRotationMode(body, 1);
    dMass mass;
    dMassSetBoxTotal(&mass, kStackBoxMass, kStackBoxSide, kStackBoxSide, kStackBoxSide);
    dBodySetMass(body, &mass);
    const core::Vec3 start = StackBoxStart(i);
    dBodySetPosition(body, start.x(), start.y(), start.z());
    dGeomID geom = dCreateBox(space_, kStackBoxSide, kStackBoxSide, kStackBoxSide);
    dGeomSetBody(geom, body);
    boxes_.push_back(body);
  }
}

RawOdeBoxStack::~RawOdeBoxStack() {
  dJointGroupDestroy(contact_group_);
  dSpaceDestroy(space_);
  dWorldDestroy(world_);
}

void RawOdeBoxStack::Simulate(double seconds) {
  const long count = std::lround(seconds / settings_.timestep);
  for (long i = 0; i < count; ++i) Step();
}

core::Vec3 RawOdeBoxStack::BoxPosition(int index) const {
  const dReal* p = dBodyGetPosition(boxes_[index]);
  return {p[0], p[1], p[2]};
}

void RawOdeBoxStack::Step() {
  dSpaceCollide(space_, this, &RawOdeBoxStack::NearCallback);
  dWorldStep(world_, settings_.timestep);
  dJointGroupEmpty(contact_group_);
  ++steps_;
}

void RawOdeBoxStack::NearCallback(void* self, dGeomID a, dGeomID b) {
  static_cast<RawOdeBoxStack*>(self)->AddContacts(a, b);
}

void RawOdeBoxStack::AddContacts(dGeomID a, dGeomID b) {
  const int capacity = std::min(settings_.max_contacts, kContactCapacity);
  const int count = dCollide(a, b, capacity, &scratch_[0].geom, sizeof(dContact));
  for (int i = 0; i < count; ++i) {
    dContact& contact = scratch_[i];
    contact.surface = {};
    contact.surface.mode = dContactApprox1;
    contact.surface.mu = kStackFriction;
    dJointID joint = dJointCreateContact(world_, contact_group_, &contact);
    dJointAttach(joint, dGeomGetBody(a), dGeomGetBody(b));
  }
  contact_joints_ += count;
}

}  // namespace lamina::bench
