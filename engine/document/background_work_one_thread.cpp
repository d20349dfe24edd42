// BackgroundWork in a page built without threads: the work runs at once, inside start() (see background_work.h).
#include <utility>

#include "document/background_work.h"

namespace meshedit {

struct BackgroundWork::Thread {};

BackgroundWork::BackgroundWork() = default;

BackgroundWork::~BackgroundWork() = default;

bool BackgroundWork::threaded() { return false; }

bool BackgroundWork::start(std::function<void()> work) {
  if (busy_) return false;
  busy_ = true;
  work();
  done_.store(true, std::memory_order_release);
  return true;
}

void BackgroundWork::take() { busy_ = false; }

}  // namespace meshedit
