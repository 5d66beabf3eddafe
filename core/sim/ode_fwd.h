// SPDX-License-Identifier: MIT
// ODE's opaque types (ode/common.h) and owners of its handles, so that headers that hold ODE
// handles do not pull in ODE: only the simulator's source files include <ode/ode.h>.
#pragma once

#include <memory>

struct dxWorld;
struct dxBody;
struct dxJoint;
struct dxJointGroup;
struct dContact;
struct dJointFeedback;

namespace lamina::core {

struct OdeWorldDeleter {
  void operator()(dxWorld* world) const;  ///< dWorldDestroy
};
struct OdeJointGroupDeleter {
  void operator()(dxJointGroup* group) const;  ///< dJointGroupDestroy
};
using OdeWorldPtr = std::unique_ptr<dxWorld, OdeWorldDeleter>;
using OdeJointGroupPtr = std::unique_ptr<dxJointGroup, OdeJointGroupDeleter>;

}  // namespace lamina::core
