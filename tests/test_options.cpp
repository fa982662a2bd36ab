#include <catch2/catch.hpp>

#include "apps/cli/options.hpp"

using namespace nephele::cli;

TEST_CASE("options reject bad values with the option's name and allowed range", "[cli]") {
  int size = 512;
  float step = 0.006f;
  Options o("generate", "test");
  o.add_int("--size", &size, 1, 16384, "size");
  o.add_float("--step", &step, 0.0, 10.0, "step");
  auto message = [&](std::vector<std::string> args) {
    try {
      o.parse(args);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(message({"--size", "0"}), Catch::Contains("--size") && Catch::Contains("1 to 16384"));
  CHECK_THAT(message({"--size", "12.5"}), Catch::Contains("not an integer"));
  CHECK_THAT(message({"--step", "nan"}), Catch::Contains("--step") && Catch::Contains("0 to 10"));
  CHECK_THAT(message({"--step", "inf"}), Catch::Contains("--step"));
  CHECK_THAT(message({"--step", "1e999"}), Catch::Contains("--step"));
  CHECK_THAT(message({"--step", "0.1x"}), Catch::Contains("not a number"));
  CHECK_THAT(message({"--size"}), Catch::Contains("a value is required"));
  CHECK_THAT(message({"--colour", "red"}), Catch::Contains("unknown argument '--colour'"));
  CHECK(message({"--size=64", "--step", "0.5"}).empty());
  CHECK(size == 64);
  CHECK(step == 0.5f);
}

TEST_CASE("help lists every option with its range and default", "[cli]") {
  int size = 512;
  Options o("generate", "summary");
  o.add_int("--size", &size, 1, 16384, "texels per face");
  CHECK_FALSE(o.parse({"--help"}));
  CHECK_THAT(o.help(), Catch::Contains("--size") && Catch::Contains("[1..16384]") && Catch::Contains("default 512"));
}
