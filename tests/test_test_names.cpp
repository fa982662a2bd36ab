// ctest runs each Catch2 test by its name as a filter (catch_discover_tests): a ';' splits the
// name into list items, so the filter matches no test, and "No tests ran" counts as passed; a
// name starting with '-' is read as an option. Such a test never runs. This keeps names safe.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

TEST_CASE("every test name is one ctest filter that can match: no semicolon and no leading dash", "[fast][tests]") {
  namespace fs = std::filesystem;
  const std::regex test_case(R"re(TEST_CASE\s*\(\s*"([^"]*)")re");
  std::vector<std::string> bad;
  int names = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(NEPHELE_SOURCE_DIR) / "tests")) {
    if (entry.path().extension() != ".cpp") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string source = text.str();
    for (std::sregex_iterator it(source.begin(), source.end(), test_case), end; it != end; ++it) {
      const std::string name = (*it)[1].str();
      ++names;
      if (name.find(';') != std::string::npos || (!name.empty() && name.front() == '-'))
        bad.push_back(entry.path().filename().string() + ": " + name);
    }
  }
  CHECK(names > 300);  // the scan found the suite's tests
  std::string listed;
  for (const auto& b : bad) listed += b + "\n";
  INFO(listed);
  CHECK(bad.empty());
}
