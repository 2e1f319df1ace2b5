// KHR_debug error capture: every GL error or high-severity message is counted and kept, so
// tests can assert that a run ended with zero GL errors.
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
// Polls glGetError too, for contexts without KHR_debug; returns the running error count.
int checkErrors(const char* where);

}  // namespace npr::gl
