// grade_bench: prints the wall time to grade one submission (the correct solutions, tests/exercise/solutions)
// against the six parts' suites and against the whole assignment (tests/grading/suites/all.lua): one child
// process per test, as `meshedit grade` does. Not a test: no timing is asserted anywhere. Each figure is the
// minimum over --reps runs.
//
//   grade_bench [--reps R]     default: 3 reps
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "bench/bench_support.h"
#include "grade/grader.h"
#include "grade/submission.h"
#include "grade/suite.h"

using meshedit::bench::arg;
using meshedit::bench::min_ms;

int main(int argc, char** argv) {
  using namespace meshedit;
  const int reps = static_cast<int>(std::max(1L, arg(argc, argv, "--reps", 3)));
  const std::filesystem::path source = MESHEDIT_SOURCE_DIR;
  try {
    const Submission solutions = Submission::read(source / "tests" / "exercise" / "solutions");
    std::printf("grading tests/exercise/solutions, minimum of %d runs\n", reps);
    for (const char* part : {"curve", "patch", "normals", "flip", "split", "upsample", "all"}) {
      const auto suite = Suite::load(source / "tests" / "grading" / "suites" / (std::string(part) + ".lua"));
      GradeReport report;
      const double best = min_ms(
          reps, [] {}, [&] { report = grade(*suite, solutions); });
      std::printf("  %-9s %2zu tests  %5.1f / %-4.0f points  %8.1f ms\n", part, report.tests.size(), report.score,
                  report.max_score, best);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "grade_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
