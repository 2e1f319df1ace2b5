// The renderer's programs, built on first use and kept: toggling features back and forth
// costs no rebuild. Asked for by typed variants (programs/program_variants.h: anything a
// `programSource(variant)` found by argument lookup turns into a ProgramSource) and keyed by
// that source (its files and #define lines), so the key can never leave out a field that
// changes the program: two variants that give the same source are the same program.
// Bounded: the combinations of paths, match modes, palettes and features a user walks through
// are many, and each program holds about a megabyte of compiled code on llvmpipe (a ten-minute
// soak built 121 and grew by 97 MB), so past `capacity` the least recently used ones go, at the
// start of a frame (a program asked for during a frame stays valid until the next).
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "renderer/core/result.h"
#include "renderer/gl/program_source.h"
#include "renderer/gl/shader_program.h"

namespace npr::gl {

// The cache's key for a program's source: its files and #define lines, in order.
std::string programKey(const ProgramSource& source);

class ProgramCache {
 public:
  static constexpr std::size_t kDefaultCapacity = 48;
  explicit ProgramCache(std::size_t capacity = kDefaultCapacity) : capacity_(capacity) {}

  // The program for `variant`; a build adds one to `builds` (the frame's shader-build counter).
  template <class Variant>
  [[nodiscard]] Result<ShaderProgram*> get(const Variant& variant, int& builds) {
    return get(programSource(variant), builds);
  }
  [[nodiscard]] Result<ShaderProgram*> get(const ProgramSource& source, int& builds);
  // Starts a frame: drops the least recently used programs beyond the capacity. Pointers from
  // get() are valid until the next call.
  void startFrame();
  std::size_t size() const { return programs_.size(); }
  std::size_t evictions() const { return evictions_; }

 private:
  struct Entry {
    ShaderProgram program;
    std::uint64_t lastUse = 0;
  };
  std::map<std::string, Entry> programs_;
  std::size_t capacity_;
  std::uint64_t frame_ = 0;
  std::size_t evictions_ = 0;
};

}  // namespace npr::gl
