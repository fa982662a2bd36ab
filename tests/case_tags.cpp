#include "case_tags.hpp"

// Listeners need the reporter interfaces of the single header.
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

namespace nephele::test {
namespace {

struct CurrentTest {
  std::string name;
  bool tagged_fast = false, tagged_optional = false;
  bool slow = false;
};

CurrentTest& current() {
  static CurrentTest test;
  return test;
}

class TestKindListener : public Catch::TestEventListenerBase {
 public:
  using TestEventListenerBase::TestEventListenerBase;
  void testCaseStarting(Catch::TestCaseInfo const& info) override {
    CurrentTest& t = current();
    t.name = info.name;
    t.tagged_fast = std::find(info.tags.begin(), info.tags.end(), "fast") != info.tags.end();
    t.tagged_optional = std::find(info.tags.begin(), info.tags.end(), "optional") != info.tags.end();
    t.slow = false;
  }
  void testCaseEnded(Catch::TestCaseStats const&) override {
    const char* file = std::getenv("NEPHELE_TEST_KINDS");
    if (file != nullptr && *file != '\0')
      std::ofstream(file, std::ios::app) << (current().slow ? "slow" : "fast") << '\t' << current().name << '\n';
  }
};

}  // namespace

void starting_slow_work(const char* what) {
  CurrentTest& t = current();
  t.slow = true;
  if (t.tagged_fast) FAIL("a [fast] test starts " << what << ": remove its [fast] tag (docs/testing.md)");
}

void skip_case(const std::string& why) {
  const char* ci = std::getenv("CI");
  if (!current().tagged_optional && ci != nullptr && std::string(ci) == "true")
    FAIL("would skip under CI=true, where the set-up installs what the suite needs: " << why);
  WARN("skipped: " << why);
}

}  // namespace nephele::test

using TestKindListener = nephele::test::TestKindListener;  // the macro pastes the name
CATCH_REGISTER_LISTENER(TestKindListener)
