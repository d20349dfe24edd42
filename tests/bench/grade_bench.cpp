// grade_bench: prints the wall time to grade one submission (the correct solutions, tests/script/solutions)
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

#include "grade/grader.h"
#include "grade/submission.h"
#include "grade/suite.h"

namespace {

using Clock = std::chrono::steady_clock;

long arg(int argc, char** argv, const char* name, long fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) return std::strtol(argv[i + 1], nullptr, 10);
  }
  return fallback;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace meshedit;
  const int reps = static_cast<int>(std::max(1L, arg(argc, argv, "--reps", 3)));
  const std::filesystem::path source = MESHEDIT_SOURCE_DIR;
  try {
    const Submission solutions = Submission::read(source / "tests" / "script" / "solutions");
    std::printf("grading tests/script/solutions, minimum of %d runs\n", reps);
    for (const char* part : {"curve", "patch", "normals", "flip", "split", "upsample", "all"}) {
      const auto suite = Suite::load(source / "tests" / "grading" / "suites" / (std::string(part) + ".lua"));
      double best = 1e300;
      GradeReport report;
      for (int i = 0; i < reps; ++i) {
        const auto start = Clock::now();
        report = grade(*suite, solutions);
        best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      }
      std::printf("  %-9s %2zu tests  %5.1f / %-4.0f points  %8.1f ms\n", part, report.tests.size(), report.score,
                  report.max_score, best);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "grade_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
