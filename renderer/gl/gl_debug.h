// KHR_debug error capture: every GL error or high-severity message is counted and kept, so
// tests can assert that a run ended with zero GL errors. Program misuse the renderer detects
// itself (see shader_program.h) is recorded the same way.
#pragma once

#include <string>
#include <vector>

namespace npr::gl {

// Installs the debug callback on the current context (needs a debug context for full output).
// Returns false when KHR_debug is unavailable; errors are then found by glGetError polling.
bool installDebugOutput();
int errorCount();
std::vector<std::string> errorMessages();
void resetErrors();
// Records a misuse of GL that GL itself cannot see (a uniform name no shader declares), so it
// fails tests and headless runs exactly as a GL error does.
void reportError(const std::string& message);
// Polls glGetError too, for contexts without KHR_debug; returns the running error count.
int checkErrors(const char* where);

}  // namespace npr::gl
