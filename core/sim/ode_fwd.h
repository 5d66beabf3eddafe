// SPDX-License-Identifier: MIT
// ODE's opaque types (ode/common.h), so that headers that hold ODE handles do not pull in ODE:
// only the simulator's source files include <ode/ode.h>.
#pragma once

struct dxWorld;
struct dxBody;
struct dxJoint;
struct dxJointGroup;
