#include "ui/cli/logging.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace nibrig::ui::cli {

void configure_logging(int verbosity) {
  auto logger = spdlog::get("nibrig");
  if (!logger) logger = spdlog::stderr_color_mt("nibrig");
  logger->set_pattern("%^%l%$: %v");
  switch (verbosity) {
    case kQuiet:
      logger->set_level(spdlog::level::err);
      break;
    case 0:
      logger->set_level(spdlog::level::warn);
      break;
    case 1:
      logger->set_level(spdlog::level::info);
      break;
    default:
      logger->set_level(spdlog::level::debug);
      break;
  }
  spdlog::set_default_logger(logger);
}

bool warnings_shown() {
  const auto logger = spdlog::get("nibrig");
  return !logger || logger->should_log(spdlog::level::warn);
}

}  // namespace nibrig::ui::cli
