// Checking and reading user files (see input_file.h).
#include "renderer/core/input_file.h"

#include <cstdio>
#include <filesystem>
#include <memory>

namespace npr {
namespace fs = std::filesystem;

namespace {
std::string mib(std::uintmax_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

const char* article(InputKind k) {
  switch (k) {
    case InputKind::Mesh: return "a mesh file";
    case InputKind::Palette: return "a palette file";
    case InputKind::Image: return "an image";
    case InputKind::MaterialLibrary: return "a material library (.mtl)";
  }
  return "a file";
}

std::uintmax_t limit(InputKind k) {
  switch (k) {
    case InputKind::Mesh: return kMaxModelFileBytes;
    case InputKind::Palette: return kMaxPaletteFileBytes;
    case InputKind::Image: return kMaxImageFileBytes;
    case InputKind::MaterialLibrary: return kMaxMaterialFileBytes;
  }
  return 0;
}
}  // namespace

Result<std::uintmax_t> checkInputFile(const std::string& path, InputKind kind) {
  const std::string what = article(kind);
  const std::uintmax_t maxBytes = limit(kind);
  if (path.empty()) return Error{"no file named (empty path) where " + what + " was expected"};
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) return Error{path + ": no such file (expected " + what + ")"};
  if (fs::is_directory(st)) return Error{path + ": is a directory, not " + what};
  if (!fs::is_regular_file(st))
    return Error{path + ": is a device, pipe or socket, not a regular file; refusing to read it as " + what};
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return Error{path + ": cannot read its size (" + ec.message() + ")"};
  if (size > maxBytes)
    return Error{path + ": is " + mib(size) + ", larger than the " + mib(maxBytes) + " allowed for " + what};
  return size;
}

Result<std::string> readInputFile(const std::string& path, InputKind kind) {
  Result<std::uintmax_t> size = checkInputFile(path, kind);
  if (!size) return Error{size.error()};
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return Error{path + ": cannot be opened for reading (permissions?)"};
  std::string data;
  // The size was checked against the limit; a file that grows meanwhile is read only that far.
  data.resize(static_cast<std::size_t>(*size));
  const std::size_t got = data.empty() ? 0 : std::fread(data.data(), 1, data.size(), f.get());
  if (std::ferror(f.get())) return Error{path + ": read error"};
  data.resize(got);
  return data;
}

}  // namespace npr
