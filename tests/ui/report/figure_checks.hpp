// Checks shared by the report figures' tests: what a folder holds, that nothing is drawn at an
// image's border, and that bad input is refused without touching the target file.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace nibrig::test {

// File names in a folder, sorted.
std::vector<std::string> names_in(const std::filesystem::path& dir);

// A margin of 3 px around the image must stay white: a clipped label or line would reach it.
void expect_white_border(const std::filesystem::path& png);

// `write` must throw std::invalid_argument naming the figure's title (in quotes) and `fault`, and
// leave an existing file untouched and nothing else behind.
void expect_rejected(const std::function<void(const std::filesystem::path&)>& write,
                     const std::string& title, const std::string& fault);

}  // namespace nibrig::test
