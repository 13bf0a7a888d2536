#include "tests/ui/report/figure_checks.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "tests/support/test_paths.hpp"
#include "tests/ui/report/png_reader.hpp"

namespace nibrig::test {

namespace fs = std::filesystem;

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void expect_white_border(const fs::path& png) {
  const auto img = decode_png(png);
  const ui::report::Rgb white{255, 255, 255};
  int dark = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const bool border = x < 3 || y < 3 || x >= img.width - 3 || y >= img.height - 3;
      if (border && !near(img.at(x, y), white, 0)) ++dark;
    }
  }
  EXPECT_EQ(dark, 0) << png << " has drawing at its border";
}

void expect_rejected(const std::function<void(const fs::path&)>& write, const std::string& title,
                     const std::string& fault) {
  const auto dir = scratch_dir("report_rejects");
  const auto target = dir / "figure.png";
  { std::ofstream(target) << "previous content"; }
  try {
    write(target);
    ADD_FAILURE() << "accepted input with: " << fault;
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), ::testing::AllOf(::testing::HasSubstr("\"" + title + "\""),
                                           ::testing::HasSubstr(fault)));
  }
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"figure.png"});
  std::ifstream in(target);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "previous content");
}

}  // namespace nibrig::test
