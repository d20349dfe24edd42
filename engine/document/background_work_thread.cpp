// BackgroundWork on the desktop: the work on a std::thread of its own (see background_work.h).
#include <thread>
#include <utility>

#include "document/background_work.h"

namespace meshedit {

struct BackgroundWork::Thread {
  std::thread thread;
};

BackgroundWork::BackgroundWork() : thread_(std::make_unique<Thread>()) {}

BackgroundWork::~BackgroundWork() { take(); }

bool BackgroundWork::threaded() { return true; }

bool BackgroundWork::start(std::function<void()> work) {
  if (busy_) return false;
  done_.store(false, std::memory_order_relaxed);
  thread_->thread = std::thread([this, work = std::move(work)] {
    work();
    done_.store(true, std::memory_order_release);
  });
  busy_ = true;
  return true;
}

void BackgroundWork::take() {
  if (thread_->thread.joinable()) thread_->thread.join();
  busy_ = false;
}

}  // namespace meshedit
