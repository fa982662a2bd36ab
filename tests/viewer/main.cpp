// The test runner: the command server is forked first (command_server.hpp), then Catch runs.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "command_server.hpp"
#include "core/large_pages.hpp"

int main(int argc, char** argv) {
  nephele::core::use_large_pages();
  nephele::test::start_command_server();
  return Catch::Session().run(argc, argv);
}
