// The tests of nephele view's window (tests/viewer): run by ctest under xvfb-run -a.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
