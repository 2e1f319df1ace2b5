// OpenMesh reports each face its halfedge structure refuses on a global error stream; the
// mesh builder and the feature edges count them instead. Both may build at once (objects'
// edges on several threads, a load on its own), so the stream is silenced while any holds
// this and restored by the last: it is switched only when no other holds it.
#pragma once

#include <mutex>

#include <OpenMesh/Core/System/omstream.hh>

namespace npr {

class SilencedOmerr {
 public:
  SilencedOmerr() {
    std::lock_guard<std::mutex> lock(mutex());
    if (holders()++ == 0) omerr().disable();
  }
  ~SilencedOmerr() {
    std::lock_guard<std::mutex> lock(mutex());
    if (--holders() == 0) omerr().enable();
  }
  SilencedOmerr(const SilencedOmerr&) = delete;
  SilencedOmerr& operator=(const SilencedOmerr&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static int& holders() {
    static int n = 0;
    return n;
  }
};

}  // namespace npr
