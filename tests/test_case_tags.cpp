// The promises of the tags [fast] and [optional] (tests/case_tags.hpp), checked by running
// hidden probe cases of this executable in a process of their own.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <string>

#include "case_tags.hpp"
#include "cli_support.hpp"
#include "gl_support.hpp"

using namespace nephele;

TEST_CASE("probe: a case that skips", "[.][probe-skip]") { test::skip_case("probe-reason"); }
TEST_CASE("probe: an optional case that skips", "[.][probe-optional-skip][optional]") {
  test::skip_case("probe-reason");
}
TEST_CASE("probe: a fast case that starts a GL context", "[.][probe-fast-gl][fast]") { test::test_context(); }
TEST_CASE("probe: a fast case that starts a subprocess", "[.][probe-fast-run][fast]") { test::run_command("true"); }

TEST_CASE("under CI=true only an [optional] case may skip, and a [fast] case may start no GL context or subprocess",
          "[cli]") {
  const std::string self = "/proc/" + std::to_string(::getpid()) + "/exe";
  const auto probe = [&](const std::string& environment, const std::string& tag) {
    return test::run_command(environment + " " + self + " \"[" + tag + "]\"");
  };
  // Skipping: a warning on a developer's machine, a failure in CI unless the case is optional.
  const test::Run local = probe("CI=", "probe-skip");
  CHECK(local.exit_code == 0);
  CHECK_THAT(local.output, Catch::Contains("skipped: probe-reason"));
  const test::Run ci = probe("CI=true", "probe-skip");
  CHECK(ci.exit_code != 0);
  CHECK_THAT(ci.output, Catch::Contains("would skip under CI=true") && Catch::Contains("probe-reason"));
  CHECK(probe("CI=true", "probe-optional-skip").exit_code == 0);
  // A [fast] case that does slow work fails, naming it.
  const test::Run gl = probe("", "probe-fast-gl");
  CHECK(gl.exit_code != 0);
  CHECK_THAT(gl.output, Catch::Contains("a [fast] test starts an OpenGL context"));
  const test::Run sub = probe("", "probe-fast-run");
  CHECK(sub.exit_code != 0);
  CHECK_THAT(sub.output, Catch::Contains("a [fast] test starts a subprocess"));
}
