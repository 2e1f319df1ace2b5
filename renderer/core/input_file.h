// The one gate every file a user hands us passes before anything reads it: models, palette
// files, palette images, backgrounds. Devices, FIFOs and sockets would hang a read (a palette
// entry naming /dev/zero never ends), and an oversized file would exhaust memory, so both are
// refused with a message that names the file, before the first byte is read.
#pragma once

#include <cstdint>
#include <string>

#include "renderer/core/result.h"

namespace npr {

enum class InputKind { Mesh, Palette, Image, MaterialLibrary };

// Limits on what one file may be: generous for real assets, far below this machine's memory.
inline constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t(4) << 30;    // 4 GiB
inline constexpr std::uintmax_t kMaxPaletteFileBytes = std::uintmax_t(1) << 20;  // 1 MiB of text
inline constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t(1) << 30;    // 1 GiB
inline constexpr std::uintmax_t kMaxMaterialFileBytes = std::uintmax_t(64) << 20;  // 64 MiB of .mtl text

// Succeeds with the file's size when `path` is a readable regular file within its kind's limit.
[[nodiscard]] Result<std::uintmax_t> checkInputFile(const std::string& path, InputKind kind);

// Reads the whole file after checkInputFile has accepted it.
[[nodiscard]] Result<std::string> readInputFile(const std::string& path, InputKind kind);

}  // namespace npr
