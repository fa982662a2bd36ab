#pragma once
// What a test case's tags promise, checked while it runs (docs/testing.md):
// - [fast] (label `fast`): the case starts no OpenGL context and no subprocess, so `ctest -L fast`
//   is the inner loop. The helpers that start either (test::test_context, test::run_command, the
//   signal tests' spawn_nephele) call starting_slow_work, which fails a [fast] case: the tag
//   cannot drift from what the case does. With NEPHELE_TEST_KINDS=FILE each case appends
//   "fast|slow<TAB>name" to FILE, what it did (how the tags were first chosen).
// - [optional] (label `optional`): the case needs a program or a privilege that the project's
//   set-up does not install (Blender, FlightGear's data, mounting); without it, it skips with a
//   warning. skip_case is the only way to skip: under CI=true it fails a case not tagged
//   [optional], since there everything else the suite needs is installed.
#include <string>

namespace nephele::test {

void starting_slow_work(const char* what);

// Skips the rest of the case with a warning naming `why`; the caller returns after it. Under
// CI=true a case not tagged [optional] fails instead.
void skip_case(const std::string& why);

}  // namespace nephele::test
