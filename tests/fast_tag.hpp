#pragma once
// The `fast` label (docs/testing.md): a test case tagged [fast] starts no OpenGL context and no
// subprocess, so `ctest -L fast` is the inner loop. The helpers that start either
// (test::test_context, test::run_command) call starting_slow_work, which fails a [fast] test: the
// tag cannot drift from what the test does. With NEPHELE_TEST_KINDS=FILE each test case appends
// "fast|slow<TAB>name" to FILE, what it did (how the tags were first chosen).

namespace nephele::test {

void starting_slow_work(const char* what);

}  // namespace nephele::test
