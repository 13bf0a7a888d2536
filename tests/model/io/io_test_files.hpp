// Helpers for the model/io tests: write malformed inputs (plain, gzip, gzip cut short) into scratch
// folders at test time, and check that a reader fails with a message naming the file, the place and
// what was expected.
#pragma once

#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

#include "model/io/format_error.hpp"

namespace nibrig::test {

inline void write_text(const std::filesystem::path& file, std::string_view content) {
  std::ofstream out(file, std::ios::binary);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  ASSERT_TRUE(out.good()) << file;
}

// Compressed with zlib's gzopen/"wb", the way the shared data's .csv.gz files were made.
inline void write_gzip(const std::filesystem::path& file, std::string_view content) {
  gzFile gz = gzopen(file.c_str(), "wb");
  ASSERT_NE(gz, nullptr) << file;
  if (!content.empty()) {
    ASSERT_EQ(gzwrite(gz, content.data(), static_cast<unsigned>(content.size())),
              static_cast<int>(content.size()));
  }
  ASSERT_EQ(gzclose(gz), Z_OK);
}

// A gzip file cut to `keep` of its compressed size: what an interrupted download or copy leaves.
inline void write_truncated_gzip(const std::filesystem::path& file, std::string_view content,
                                 double keep) {
  write_gzip(file, content);
  const auto size = std::filesystem::file_size(file);
  std::filesystem::resize_file(file, static_cast<std::uintmax_t>(static_cast<double>(size) * keep));
}

// Runs `action`, expects a FormatError and returns its message ("" and a test failure otherwise).
inline std::string format_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const model::io::FormatError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "expected a FormatError, got another exception: " << error.what();
    return "";
  }
  ADD_FAILURE() << "expected a FormatError, nothing was thrown";
  return "";
}

// The message must name every one of `parts` (file name, line/field, the expectation).
inline void expect_message_names(const std::string& message,
                                 std::initializer_list<std::string_view> parts) {
  for (std::string_view part : parts) {
    EXPECT_NE(message.find(part), std::string::npos)
        << "message does not name \"" << part << "\":\n  " << message;
  }
}

}  // namespace nibrig::test
