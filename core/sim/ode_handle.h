// SPDX-License-Identifier: MIT
// The one-time ODE initialisation (the RAII owners of ODE handles are in ode_fwd.h). Only
// core/sim's source files include <ode/ode.h>.
#pragma once

#include <type_traits>

#include <ode/ode.h>

namespace lamina::core {

static_assert(std::is_same_v<dReal, double>, "Lamina needs ODE built in double precision");

/// Initialises ODE once per process (thread-safe) and routes its messages: errors and debug
/// messages become C++ exceptions caught at the simulator boundary instead of aborting.
void EnsureOdeInitialized();

}  // namespace lamina::core
