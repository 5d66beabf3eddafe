// SPDX-License-Identifier: MIT
#include "core/sim/ode_handle.h"

#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

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

// A world of CreateOdeWorld holds its threading implementation as its user data. ODE leaves the
// implementation's job list set when an error throws out of a step, and freeing it then trips an
// ODE assertion: such an implementation is kept (reachable, never used again) instead.
struct OdeWorldThreading {
  dThreadingImplementationID implementation = nullptr;
  bool failed = false;  ///< an error was thrown out of a step of the world
};

std::mutex& FailedThreadingMutex() {
  static std::mutex mutex;
  return mutex;
}

std::vector<dThreadingImplementationID>& FailedThreading() {
  static auto* kept = new std::vector<dThreadingImplementationID>();
  return *kept;
}

}  // namespace

void OdeWorldDeleter::operator()(dxWorld* world) const {
  auto* threading = static_cast<OdeWorldThreading*>(dWorldGetData(world));
  if (threading != nullptr) dWorldSetStepThreadingImplementation(world, nullptr, nullptr);
  dWorldDestroy(world);
  if (threading == nullptr) return;
  if (threading->failed) {
    std::lock_guard<std::mutex> lock(FailedThreadingMutex());
    FailedThreading().push_back(threading->implementation);
  } else {
    dThreadingFreeImplementation(threading->implementation);
  }
  delete threading;
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
  auto* threading = new OdeWorldThreading{dThreadingAllocateSelfThreadedImplementation()};
  dxWorld* world = dWorldCreate();
  dWorldSetStepThreadingImplementation(
      world, dThreadingImplementationGetFunctions(threading->implementation),
      threading->implementation);
  dWorldSetData(world, threading);
  return OdeWorldPtr(world);
}

void MarkOdeWorldFailed(dxWorld* world) {
  auto* threading = static_cast<OdeWorldThreading*>(dWorldGetData(world));
  if (threading != nullptr) threading->failed = true;
}

}  // namespace lamina::core
