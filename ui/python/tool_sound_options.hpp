// What a Python call that makes tool sounds reads (the bundled catalog, stylus and cached forcing
// model unless files are named), with the forcing model's fit, when a design point needs one first,
// reporting progress and stopping on the call's stop token.
#pragma once

#include <filesystem>
#include <optional>
#include <stop_token>

#include "model/design/tool_sound.hpp"
#include "model/numeric/cancellation.hpp"
#include "ui/python/long_call.hpp"

namespace nibrig::ui::python {

inline model::design::ToolSoundOptions tool_sound_options(const std::optional<std::filesystem::path>& catalog,
                                                          const std::optional<std::filesystem::path>& stylus,
                                                          const std::optional<std::filesystem::path>& forcing,
                                                          const std::stop_token& stop, const Report& report) {
  return {catalog.value_or(std::filesystem::path()), stylus.value_or(std::filesystem::path()),
          forcing.value_or(std::filesystem::path()),
          [stop, report](const model::forcing::DesignResponse&, std::size_t done, std::size_t total) {
            model::numeric::throw_if_cancelled(stop, "forcing model fit");
            report("simulating the forcing model's designs", done, total);
          }};
}

}  // namespace nibrig::ui::python
