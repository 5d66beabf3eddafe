// SPDX-License-Identifier: MIT
#include "core/sim/ode_handle.h"

#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>

#include "core/sim/ode_fwd.h"

namespace lamina::core {

namespace {

std::string FormatOdeMessage(int number, const char* format, va_list arguments) {
  char buffer[512];
  std::vsnprintf(buffer, sizeof(buffer), format, arguments);
  return "ode " + std::to_string(number) + ": " + buffer;
}

[[noreturn]] void OnOdeError(int number, const char* format, va_list arguments) {
  throw std::runtime_error(FormatOdeMessage(number, format, arguments));
}

// ODE's "LCP internal error, s <= 0" and similar messages are informational: the step still
// completes (stack.md §4); they are dropped rather than printed from inside the library
void OnOdeMessage(int, const char*, va_list) {}

}  // namespace

// a world of CreateOdeWorld holds its threading implementation as its user data
void OdeWorldDeleter::operator()(dxWorld* world) const {
  auto threading = static_cast<dThreadingImplementationID>(dWorldGetData(world));
  if (threading != nullptr) dWorldSetStepThreadingImplementation(world, nullptr, nullptr);
  dWorldDestroy(world);
  if (threading != nullptr) dThreadingFreeImplementation(threading);
}

void OdeJointGroupDeleter::operator()(dxJointGroup* group) const {
  dJointGroupDestroy(group);
}

void EnsureOdeInitialized() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    dSetErrorHandler(OnOdeError);
    dSetDebugHandler(OnOdeError);
    dSetMessageHandler(OnOdeMessage);
  });
}

OdeWorldPtr CreateOdeWorld() {
  EnsureOdeInitialized();
  dThreadingImplementationID threading = dThreadingAllocateSelfThreadedImplementation();
  dxWorld* world = dWorldCreate();
  dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(threading),
                                       threading);
  dWorldSetData(world, threading);
  return OdeWorldPtr(world);
}

}  // namespace lamina::core
