// Resident memory over a long headless sequence, read from /proc/self/statm after a tenth of
// its frames and after the last, so a run of 1,000 frames shows whether it grows.
#pragma once

#include <string>

namespace npr {

class ResidentMemory {
 public:
  explicit ResidentMemory(int frames);
  // After `done` frames of the sequence.
  void sample(int done);
  // "; resident memory 212.3 MB after frame 100, 213.0 MB after frame 1000 (+0.3%)", or empty
  // for sequences too short to say (under 20 frames) or where /proc is not there.
  std::string summary() const;

 private:
  int frames_ = 0, early_ = 0;
  double earlyMb_ = 0.0, lastMb_ = 0.0;
};

}  // namespace npr
