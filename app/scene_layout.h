// How several files are placed in one scene (--layout, the overlay's object list): as their
// files place them, or each fitted to a unit sphere and set apart in a row or a grid.
#pragma once

#include <optional>
#include <string>

namespace npr {

enum class Layout { File, Row, Grid };

inline const char* layoutName(Layout layout) {
  switch (layout) {
    case Layout::File: return "file";
    case Layout::Row: return "row";
    case Layout::Grid: return "grid";
  }
  return "file";
}

inline std::optional<Layout> parseLayout(const std::string& name) {
  for (Layout l : {Layout::File, Layout::Row, Layout::Grid})
    if (name == layoutName(l)) return l;
  return std::nullopt;
}

}  // namespace npr
