// A comment, help text or docstring that sends the reader to a section ("FORMATS.md, \"Forcing
// model\"", "ARCHITECTURE.md (\"Conventions\")") must name a section that exists: each such
// pointer in the sources is looked up among the named document's headings ("PROTOCOL.md's" is a
// possessive, not a pointer). A heading matches
// when it begins with the name (headings add the file they describe: "Forcing model
// (`forcing.json`)").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = nibrig::test::assets_dir().parent_path();

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// What a pointer's document name means: the top-level README, or the one document of that name.
const std::map<std::string, fs::path> kDocuments = {
    {"README", kSource / "README.md"},
    {"ARCHITECTURE.md", kSource / "ARCHITECTURE.md"},
    {"FORMATS.md", kSource / "model/io/FORMATS.md"},
    {"HARDWARE.md", kSource / "rig/HARDWARE.md"},
    {"PROTOCOL.md", kSource / "rig/PROTOCOL.md"},
    {"PARTS.md", kSource / "rig/PARTS.md"}};

std::vector<std::string> headings(const fs::path& document) {
  std::vector<std::string> out;
  std::istringstream lines(read_text(document));
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] == '#') {
      const auto text = line.find_first_not_of("# ");
      if (text != std::string::npos) out.push_back(line.substr(text));
    }
  return out;
}

bool has_section(const std::vector<std::string>& headings, const std::string& name) {
  for (const auto& h : headings)
    if (h.rfind(name, 0) == 0 && (h.size() == name.size() || h[name.size()] == ' ' ||
                                  h[name.size()] == '(' || h[name.size()] == ':'))
      return true;
  return false;
}

TEST(DocumentPointers, EverySectionNamedInTheSourcesExists) {
  const std::regex pointer(
      R"((README|ARCHITECTURE\.md|FORMATS\.md|HARDWARE\.md|PROTOCOL\.md|PARTS\.md),? ?\(?(?:\\?"|“|'(?!s\b))([A-Za-z][^"'”\\]*))");
  const std::set<std::string> extensions = {".hpp", ".cpp", ".h", ".c", ".py", ".pyi"};
  std::map<std::string, std::vector<std::string>> sections;
  for (const auto& [name, file] : kDocuments) sections[name] = headings(file);
  int checked = 0;
  for (const char* layer : {"rt", "playback", "rig", "model", "ui", "tests"})
    for (const auto& entry : fs::recursive_directory_iterator(kSource / layer)) {
      if (!entry.is_regular_file() || !extensions.count(entry.path().extension().string()))
        continue;
      const std::string text = read_text(entry.path());
      for (std::sregex_iterator m(text.begin(), text.end(), pointer), end; m != end; ++m) {
        const std::string document = (*m)[1], section = (*m)[2];
        if (entry.path().filename() == "doc_pointers_test.cpp") continue;  // its own examples
        ++checked;
        EXPECT_TRUE(has_section(sections.at(document), section))
            << fs::relative(entry.path(), kSource).string() << " names " << document << ", \""
            << section << "\", which " << kDocuments.at(document).filename().string()
            << " has no heading for";
      }
    }
  RecordProperty("pointers", checked);
  // The sources do point into the documents (a pattern that found nothing would pass anything).
  EXPECT_GE(checked, 15);
}

}  // namespace
}  // namespace nibrig::model::io
