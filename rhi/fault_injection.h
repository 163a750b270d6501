#pragma once
// A test hook, not a feature: makes a backend report a lost device on demand, so that the
// tests can check what `lumina render`, `lumina reference` and the viewer do when a GPU is lost
// (a TDR, a driver reset, an unplugged eGPU), which no real driver does when asked
// (docs/gi_tests.md#device-loss). Off unless the environment says otherwise:
//
//   LUMINA_FAULT_INJECT=device-lost-after-submits:N
//
// lets N submissions through (counted over every queue of the process) and then reports the
// device lost on every later submission and every wait, as VK_ERROR_DEVICE_LOST or
// DXGI_ERROR_DEVICE_REMOVED would: the backends then take their ordinary path, throwing
// rhi::DeviceLostError. What was submitted before still runs; nothing is lost for real.
#include <string>

namespace lumina::rhi::fault {

// Called by a backend's queue submit, before it submits: true when this submission must fail
// with a lost device (and every one after it). Throws rhi::Error naming the variable when
// LUMINA_FAULT_INJECT holds something it does not understand.
bool deviceLostOnSubmit();

// True once a submission reported the injected loss: waits report it too from then on.
bool deviceLost();

// What to add to the backend's error message, so that an injected loss is never mistaken for a
// real one: "; injected by LUMINA_FAULT_INJECT=device-lost-after-submits:3".
std::string injectedNote();

} // namespace lumina::rhi::fault
