// Finding, checking and loading the viewer's modules (see plugin_module.h).
#include "renderer/core/plugin_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "renderer/core/printable.h"

#ifndef NPR_MODULE_STAMP
#error "NPR_MODULE_STAMP names the module interface this binary was built with (renderer/CMakeLists.txt)"
#endif

namespace npr {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> candidates(const char* fileName) {
  std::vector<fs::path> out;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back(exe.parent_path().parent_path() / "lib" / "npr-viewer" / fileName);
#ifdef NPR_BUILD_DIR
  // Only for a binary inside the build tree, so an installed binary never picks up a module
  // from a build it did not come from.
  const std::string build = NPR_BUILD_DIR;
  if (!ec && exe.string().rfind(build + "/", 0) == 0) out.push_back(fs::path(NPR_MODULE_DIR) / fileName);
#endif
  return out;
}

Result<const void*> load(const char* fileName, const char* what) {
  std::string tried;
  for (const fs::path& path : candidates(fileName)) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
      tried += (tried.empty() ? "" : ", ") + path.string();
      continue;
    }
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = ::dlerror();
      return Error{printable(path.string(), 200) + " (for " + what + ") could not be loaded: " + printableMessage(why ? why : "unknown reason") +
                   ". Reinstall npr-viewer, or install the libraries it names."};
    }
    using StampFn = const char* (*)();
    using TableFn = const void* (*)();
    auto stamp = reinterpret_cast<StampFn>(::dlsym(handle, "npr_module_stamp"));
    auto table = reinterpret_cast<TableFn>(::dlsym(handle, "npr_module_table"));
    if (!stamp || !table || std::string(stamp()) != NPR_MODULE_STAMP)
      return Error{printable(path.string(), 200) + " (for " + what + ") belongs to another build of npr-viewer. Reinstall npr-viewer."};
    return table();
  }
  return Error{std::string("npr-viewer's module ") + fileName + " (for " + what + ") is not installed; looked in " + printable(tried, 400) +
               ". Reinstall npr-viewer."};
}

}  // namespace

Result<const void*> loadModuleTable(const char* fileName, const char* what) {
  static std::mutex mutex;
  static std::map<std::string, Result<const void*>> loaded;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = loaded.find(fileName);
  if (it == loaded.end()) it = loaded.emplace(fileName, load(fileName, what)).first;
  return it->second;
}

}  // namespace npr
