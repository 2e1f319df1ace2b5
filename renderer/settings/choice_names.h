// The names of every choice a setting makes, in one table per enum: the settings table's rows
// (app/settings/settings_table.cpp), the palette files' `match` line, reports and messages
// all read them here, so a choice is named once. The order is the one help and the overlay
// list them in.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <utility>

#include "renderer/settings/choices.h"
#include "renderer/settings/render_settings.h"

namespace npr {

template <class E>
struct ChoiceNames;  // static constexpr std::array<std::pair<const char*, E>, N> values

#define NPR_CHOICES(E, ...)                                                     \
  template <>                                                                   \
  struct ChoiceNames<E> {                                                       \
    static constexpr std::pair<const char*, E> values[] = {__VA_ARGS__};        \
  }
NPR_CHOICES(MatchMode, {"colors", MatchMode::Colors}, {"intensity", MatchMode::Intensity}, {"order", MatchMode::Order});
NPR_CHOICES(ToneModel, {"opengl", ToneModel::OpenGL}, {"gooch", ToneModel::Gooch}, {"splashback", ToneModel::Splashback},
            {"charcoal", ToneModel::Charcoal});
NPR_CHOICES(ToneRange, {"fixed", ToneRange::Fixed}, {"auto", ToneRange::Auto}, {"per-object", ToneRange::PerObject});
NPR_CHOICES(ToneBlend, {"mix", ToneBlend::Mix}, {"threshold", ToneBlend::Threshold});
NPR_CHOICES(TriangleLighting, {"auto", TriangleLighting::Auto}, {"cpu", TriangleLighting::Cpu}, {"gpu", TriangleLighting::Gpu});
NPR_CHOICES(PosePlacement, {"auto", PosePlacement::Auto}, {"cpu", PosePlacement::Cpu}, {"gpu", PosePlacement::Gpu});
NPR_CHOICES(PatternSpace, {"screen", PatternSpace::Screen}, {"anchored", PatternSpace::Anchored}, {"object", PatternSpace::Object});
NPR_CHOICES(OcclusionMethod, {"baked", OcclusionMethod::Baked}, {"screen", OcclusionMethod::Screen});
NPR_CHOICES(OutlineMethod, {"fatten", OutlineMethod::Fatten}, {"offset", OutlineMethod::Offset}, {"edges", OutlineMethod::Edges});
#undef NPR_CHOICES

// The name of `value` ("?" for a value outside the table).
template <class E>
constexpr const char* choiceName(E value) {
  for (const auto& [name, v] : ChoiceNames<E>::values)
    if (v == value) return name;
  return "?";
}

// The value named `name`, or none.
template <class E>
constexpr std::optional<E> parseChoice(std::string_view name) {
  for (const auto& [n, v] : ChoiceNames<E>::values)
    if (name == n) return v;
  return std::nullopt;
}

}  // namespace npr
