// Resident memory of a sequence (see resident_memory.h).
#include "app/headless/resident_memory.h"

#include <algorithm>
#include <cstdio>

#include <unistd.h>

namespace npr {
namespace {
constexpr int kFewestFrames = 20;

double residentMb() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0.0;
  long size = 0, resident = 0;
  const int read = std::fscanf(f, "%ld %ld", &size, &resident);
  std::fclose(f);
  return read == 2 ? double(resident) * double(sysconf(_SC_PAGESIZE)) / 1e6 : 0.0;
}
}  // namespace

ResidentMemory::ResidentMemory(int frames) : frames_(frames), early_(std::max(1, frames / 10)) {}

void ResidentMemory::sample(int done) {
  if (frames_ < kFewestFrames) return;
  if (done == early_) earlyMb_ = residentMb();
  if (done == frames_) lastMb_ = residentMb();
}

std::string ResidentMemory::summary() const {
  if (frames_ < kFewestFrames || !(earlyMb_ > 0.0) || !(lastMb_ > 0.0)) return {};
  char text[160];
  std::snprintf(text, sizeof text, "; resident memory %.1f MB after frame %d, %.1f MB after frame %d (%+.1f%%)", earlyMb_, early_, lastMb_, frames_,
                100.0 * (lastMb_ - earlyMb_) / earlyMb_);
  return text;
}

}  // namespace npr
