// RSS growth in a forked child (see peer_memory.h), read from /proc/self/statm (Linux only, like the
// rest of the benchmarks' environment).
#include "bench/peer_memory.h"

#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

namespace meshedit::bench {
namespace {

long long resident_bytes() {
  malloc_trim(0);
  long long pages = 0, resident = 0;
  if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%lld %lld", &pages, &resident) != 2) resident = -1;
    std::fclose(statm);
  } else {
    return -1;
  }
  return resident < 0 ? -1 : resident * sysconf(_SC_PAGESIZE);
}

}  // namespace

long long rss_growth_in_child(const std::function<void()>& prepare, const std::function<void()>& work) {
  int channel[2];
  if (pipe(channel) != 0) return -1;
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child < 0) {
    close(channel[0]);
    close(channel[1]);
    return -1;
  }
  if (child == 0) {
    close(channel[0]);
    long long growth = -1;
    try {
      prepare();
      const long long before = resident_bytes();
      work();
      const long long after = resident_bytes();
      if (before >= 0 && after >= 0) growth = after - before;
    } catch (...) {
      growth = -1;
    }
    const ssize_t written = write(channel[1], &growth, sizeof growth);
    _exit(written == sizeof growth ? 0 : 1);
  }
  close(channel[1]);
  long long growth = -1;
  if (read(channel[0], &growth, sizeof growth) != sizeof growth) growth = -1;
  close(channel[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return growth;
}

}  // namespace meshedit::bench
