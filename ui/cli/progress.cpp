#include "ui/cli/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <memory>

#include "ui/cli/logging.hpp"

namespace nibrig::ui::cli {

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)),
      total_(total),
      enabled_(isatty(STDERR_FILENO) == 1 && warnings_shown()) {}

Progress::~Progress() {
  if (enabled_ && done_ > 0) std::fputs("\n", stderr);
}

void Progress::advance(const std::string& item) {
  std::lock_guard lock(mutex_);
  ++done_;
  if (!enabled_) return;
  constexpr std::size_t width = 30;
  const std::size_t filled = total_ == 0 ? width : width * done_ / total_;
  std::string bar(filled, '#');
  bar.resize(width, '.');
  std::string shown = item.size() > 40 ? "..." + item.substr(item.size() - 37) : item;
  std::fprintf(stderr, "\r%s [%s] %zu/%zu %-40s", label_.c_str(), bar.c_str(), done_, total_,
               shown.c_str());
  std::fflush(stderr);
}

std::function<void(std::size_t, std::size_t)> progress_bar(std::string label) {
  auto bar = std::make_shared<std::unique_ptr<Progress>>();
  return [bar, label = std::move(label)](std::size_t done, std::size_t total) {
    if (!*bar) *bar = std::make_unique<Progress>(label, total);
    (*bar)->advance("");
    if (done == total) bar->reset();
  };
}

}  // namespace nibrig::ui::cli
