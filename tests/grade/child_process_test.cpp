// run_in_child: the report travels back, output is captured and capped, a hanging child is killed at the
// deadline, a crash is described, and the child can neither open files nor start processes.
#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include "grade/child_process.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

ChildLimits limits(double seconds) {
  ChildLimits l;
  l.wall_seconds = seconds;
  l.output_bytes = 1000;
  return l;
}

TEST(ChildProcess, ReportAndOutputComeBack) {
  const ChildResult r = run_in_child(limits(5), [] {
    std::fputs("to stdout\n", stdout);
    std::fflush(stdout);
    std::fputs("to stderr\n", stderr);
    return std::string("the report\0with a zero byte", 27);
  });
  EXPECT_TRUE(r.report_complete);
  EXPECT_EQ(r.report, std::string("the report\0with a zero byte", 27));
  EXPECT_EQ(r.out, "to stdout\n");
  EXPECT_EQ(r.err, "to stderr\n");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.signal, 0);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.filter_problem, "");
}

TEST(ChildProcess, OutputIsCappedAndDrainedSoTheChildNeverBlocks) {
  const ChildResult r = run_in_child(limits(10), [] {
    const std::string block(1 << 16, 'x');
    for (int i = 0; i < 160; ++i) {  // 10 MB, far more than a pipe holds
      if (write(1, block.data(), block.size()) < 0) break;
    }
    return std::string("done");
  });
  EXPECT_TRUE(r.report_complete);
  EXPECT_EQ(r.report, "done");
  EXPECT_EQ(r.out.size(), 1000u);
}

TEST(ChildProcess, AHangingChildIsKilledAtTheDeadline) {
  const ChildResult r = run_in_child(limits(0.3), [] {
    for (;;) pause();
    return std::string();
  });
  EXPECT_TRUE(r.timed_out);
  EXPECT_FALSE(r.report_complete);
  EXPECT_EQ(r.signal, SIGKILL);
  EXPECT_GE(r.seconds, 0.3);
  EXPECT_EQ(describe_child_end(r, 0.3).rfind("stopped after 0.3 s (time limit)", 0), 0u) << describe_child_end(r, 0.3);
}

TEST(ChildProcess, ACrashIsDescribed) {
  const ChildResult r = run_in_child(limits(5), [] {
    // The default action, as in a normal build: AddressSanitizer's own SIGSEGV handler would exit with status 1.
    std::signal(SIGSEGV, SIG_DFL);
    std::raise(SIGSEGV);
    return std::string("never");
  });
  EXPECT_FALSE(r.report_complete);
  EXPECT_EQ(r.signal, SIGSEGV);
  EXPECT_EQ(r.report, "");
  const std::string text = describe_child_end(r, 5);
  EXPECT_NE(text.find("killed by signal 11"), std::string::npos) << text;
  EXPECT_NE(text.find("out of memory"), std::string::npos) << text;
}

TEST(ChildProcess, AnExceptionInTheBodyIsAnExitWithoutReport) {
  const ChildResult r = run_in_child(limits(5), []() -> std::string { throw std::runtime_error("boom"); });
  EXPECT_FALSE(r.report_complete);
  EXPECT_EQ(r.exit_code, 122);
  EXPECT_EQ(r.err, "grading child: boom\n");
  EXPECT_EQ(describe_child_end(r, 5), "the test process exited with status 122 without a report");
}

TEST(ChildProcess, TheChildCannotOpenFilesOrStartProcesses) {
  const auto dir = testing::scratch_dir();
  const std::string path = (dir / "secret.txt").string();
  {
    FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("hidden tests", f);
    std::fclose(f);
  }
  const ChildResult r = run_in_child(limits(5), [&] {
    std::string report;
    const int read_fd = open(path.c_str(), O_RDONLY);
    report += read_fd < 0 && errno == EACCES ? "read denied;" : "read allowed;";
    const int write_fd = open((path + ".new").c_str(), O_WRONLY | O_CREAT, 0644);
    report += write_fd < 0 && errno == EACCES ? "create denied;" : "create allowed;";
    report += unlink(path.c_str()) != 0 && errno == EACCES ? "unlink denied;" : "unlink allowed;";
    const pid_t pid = fork();
    if (pid == 0) _exit(0);
    report += pid < 0 ? "fork denied" : "fork allowed";
    return report;
  });
  ASSERT_EQ(r.filter_problem, "");
  EXPECT_EQ(r.report, "read denied;create denied;unlink denied;fork denied");
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".new"));
}

TEST(ChildProcess, MemoryBeyondTheAddressSpaceLimitFails) {
  ChildLimits l = limits(10);
  l.memory_bytes = size_t(64) << 20;
  const ChildResult r = run_in_child(l, [] {
    try {
      std::string big(size_t(512) << 20, 'x');
      // Written through a volatile pointer, so no compiler may elide the allocation (clang does without it).
      volatile char* last = big.data() + big.size() - 1;
      *last = 'y';
      return std::string("allocated ") + big.substr(big.size() - 1);
    } catch (const std::bad_alloc&) {
      return std::string("bad_alloc");
    }
  });
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "RLIMIT_AS is not set under AddressSanitizer";
#endif
  EXPECT_EQ(r.report, "bad_alloc");
}

}  // namespace
}  // namespace meshedit
