// SPDX-License-Identifier: MIT
// The 10-box stack of stacktest.xml written directly on ODE, the way an ODE program would: box
// geoms in a simple space, dSpaceCollide + dCollide for contacts, one contact joint per contact
// point with Coulomb friction, dWorldStep. It is the baseline for Lamina's overhead.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <ode/ode.h>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::bench {

class RawOdeBoxStack {
 public:
  /// The stack at its start; ERP, CFM, gravity, step and contacts per pair from `settings`.
  explicit RawOdeBoxStack(const core::SimSettings& settings = {});
  ~RawOdeBoxStack();
  RawOdeBoxStack(const RawOdeBoxStack&) = delete;
  RawOdeBoxStack& operator=(const RawOdeBoxStack&) = delete;

  /// Advances by `seconds` in steps of the settings' time step.
  void Simulate(double seconds);
  /// Centre of box `index` (0 = bottom).
  core::Vec3 BoxPosition(int index) const;
  long steps() const { return steps_; }
  /// Contact joints over all steps.
  long contact_joints() const { return contact_joints_; }

 private:
  // dCollide writes at most this many contacts per geom pair
  static constexpr int kContactCapacity = 64;

  static void NearCallback(void* self, dGeomID a, dGeomID b);
  void AddContacts(dGeomID a, dGeomID b);
  void Step();

  core::SimSettings settings_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;  // owns the geoms
  dJointGroupID contact_group_ = nullptr;
  std::vector<dBodyID> boxes_;
  std::array<dContact, kContactCapacity> scratch_{};
  long contact_joints_ = 0;
  long steps_ = 0;
};

}  // namespace lamina::bench
