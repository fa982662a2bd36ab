// Progress reports of long work (src/core/progress.hpp).
#include <catch2/catch.hpp>

#include <cstdio>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

#include "cli_support.hpp"
#include "core/progress.hpp"

using nephele::core::Progress;

namespace {

// Everything written to a temporary stream.
std::string contents(std::FILE* stream) {
  std::fflush(stream);
  std::rewind(stream);
  std::string text;
  char buffer[256];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, stream)) > 0) text.append(buffer, n);
  return text;
}

Progress::Settings immediate(std::FILE* stream, bool terminal) {
  Progress::Settings s;
  s.terminal = terminal;
  s.quiet_below_s = 0;
  s.line_interval_s = 0;
  s.redraw_interval_s = 0;
  s.heartbeat = false;  // only the updates below print, so the output is exactly known
  s.stream = stream;
  return s;
}

}  // namespace

TEST_CASE("a progress report states the fraction, the time so far and the time left at the average rate",
          "[fast][progress]") {
  // Half done after 10 s at a constant rate leaves 10 s.
  CHECK(Progress::format("generate", "warp", 0.5, 10.0, false) == "generate:  50% (10.0 s, about 10 s left) warp");
  // Before 1% nothing can be estimated; at the end nothing is left.
  CHECK(Progress::format("generate", "", 0.001, 3.0, false) == "generate:   0% (3.0 s)");
  CHECK(Progress::format("generate", "done", 1.0, 20.0, false) == "generate: 100% (20.0 s) done");
  // A bar of 24 cells, a quarter filled.
  CHECK_THAT(Progress::format("render", "", 0.25, 1.0, true), Catch::Contains("[######                  ]"));
}

TEST_CASE("progress goes to plain lines off a terminal and to one redrawn line on a terminal", "[fast][progress]") {
  std::FILE* lines = std::tmpfile();
  {
    Progress p("generate", 4, immediate(lines, false));
    p.update(1, "curl");
    p.update(2, "warp");
  }
  const std::string plain = contents(lines);
  CHECK_THAT(plain, Catch::Contains("generate:  25%") && Catch::Contains("curl\n") && Catch::Contains("100%"));
  CHECK(plain.find('\r') == std::string::npos);
  std::fclose(lines);

  std::FILE* terminal = std::tmpfile();
  {
    Progress p("generate", 4, immediate(terminal, true));
    p.update(2, "warp");
  }
  const std::string drawn = contents(terminal);
  CHECK_THAT(drawn, Catch::StartsWith("\rgenerate: [############") && Catch::Contains("100%") && Catch::EndsWith("\n"));
  CHECK(drawn.find("\rgenerate: [########################] 100%") != std::string::npos);
  std::fclose(terminal);
}

TEST_CASE("progress ended by an error says stopped at the fraction reached, not done", "[fast][progress]") {
  std::FILE* stream = std::tmpfile();
  try {
    Progress p("render", 4, immediate(stream, false));
    p.update(1, "global cover");
    throw std::runtime_error("a bad map");
  } catch (const std::runtime_error&) {
  }
  const std::string lines = contents(stream);
  CHECK_THAT(lines, Catch::Contains("render:  25%") && Catch::EndsWith("stopped\n"));
  CHECK(lines.find("done") == std::string::npos);
  CHECK(lines.find("100%") == std::string::npos);
  std::fclose(stream);
}

TEST_CASE("the heartbeat reports a step that runs long without updates of its own", "[fast][progress]") {
  std::FILE* stream = std::tmpfile();
  {
    Progress::Settings s;
    s.terminal = false;
    s.quiet_below_s = 0.05;
    s.line_interval_s = 0.2;
    s.stream = stream;
    Progress p("render", 2, s);
    p.update(1, "clouds");
    // One update, then silence for 1.3 s: the heartbeat repeats the line (every 0.5 s at most).
    std::this_thread::sleep_for(std::chrono::milliseconds(1300));
  }
  const std::string lines = contents(stream);
  std::size_t repeats = 0;
  for (std::size_t at = lines.find("50%"); at != std::string::npos; at = lines.find("50%", at + 1)) ++repeats;
  CHECK(repeats >= 2);
  CHECK_THAT(lines, Catch::Contains("clouds") && Catch::Contains("100%"));
  std::fclose(stream);
}

TEST_CASE("quiet progress and work shorter than the threshold print nothing", "[fast][progress]") {
  std::FILE* stream = std::tmpfile();
  {
    Progress::Settings quiet = immediate(stream, false);
    quiet.enabled = false;
    Progress p("generate", 2, quiet);
    p.update(1, "warp");
  }
  {
    Progress::Settings brief = immediate(stream, false);
    brief.quiet_below_s = 3600;
    Progress p("generate", 2, brief);
    p.update(1, "warp");
  }
  CHECK(contents(stream).empty());
  std::fclose(stream);
}

TEST_CASE("generate takes --quiet and prints no progress with it", "[progress][cli]") {
  nephele::test::TemporaryDirectory out;
  const auto r = nephele::test::run("generate --size 8 --iterations 2 --quiet --out " + out.path.string());
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("generate:") == std::string::npos);
}
