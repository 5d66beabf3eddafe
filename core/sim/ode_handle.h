// SPDX-License-Identifier: MIT
// RAII owners for ODE handles and the one-time ODE initialisation. Only core/sim/ode_*.cpp and
// the simulator include <ode/ode.h>.
#pragma once

#include <memory>
#include <type_traits>

#include <ode/ode.h>

namespace lamina::core {

static_assert(std::is_same_v<dReal, double>, "Lamina needs ODE built in double precision");

/// Initialises ODE once per process (thread-safe) and routes its messages: errors and debug
/// messages become C++ exceptions caught at the simulator boundary instead of aborting.
void EnsureOdeInitialized();

struct OdeWorldDeleter {
  void operator()(dxWorld* world) const { dWorldDestroy(world); }
};
struct OdeJointGroupDeleter {
  void operator()(dxJointGroup* group) const { dJointGroupDestroy(group); }
};
using OdeWorldPtr = std::unique_ptr<dxWorld, OdeWorldDeleter>;
using OdeJointGroupPtr = std::unique_ptr<dxJointGroup, OdeJointGroupDeleter>;

}  // namespace lamina::core
