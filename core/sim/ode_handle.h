// SPDX-License-Identifier: MIT
// The one-time ODE initialisation (the RAII owners of ODE handles are in ode_fwd.h). Only
// core/sim's source files include <ode/ode.h>.
#pragma once

#include <type_traits>

#include <ode/ode.h>

#include "core/sim/ode_fwd.h"

namespace lamina::core {

static_assert(std::is_same_v<dReal, double>, "Lamina needs ODE built in double precision");

/// Initialises ODE once per process (thread-safe) and routes its messages: errors and debug
/// messages become C++ exceptions caught at the simulator boundary instead of aborting.
void EnsureOdeInitialized();

/// A new ODE world with its own self-threaded step implementation (its user data, freed with
/// the world by OdeWorldDeleter). Without one every world
/// shares ODE's global default, whose job list is not thread-safe: two simulators stepping in
/// two threads (batch runs, core/batch) crash inside dWorldStep.
OdeWorldPtr CreateOdeWorld();
/// Call when an ODE error was thrown out of a step of `world` (a CreateOdeWorld world): its
/// threading implementation is then kept rather than freed with the world (ODE cannot free it).
void MarkOdeWorldFailed(dxWorld* world);

}  // namespace lamina::core
