// BackgroundWork: one piece of work at a time, run off the caller's thread where the host has threads (a std::thread
// in the desktop build: background_work_thread.cpp), else at once on the caller's thread (a page, built without
// threads: background_work_one_thread.cpp). The Exercises tab runs the student's code through it, so a runaway loop
// does not hold the window's frames.
//
// Invariants:
// - The work must not throw (wrap it: what it makes is the caller's to keep), and must not touch what the caller's
//   thread uses until done() is true; done() is read with acquire order, so everything the work wrote is visible then.
// - busy() from start() until take(); start() while busy() is refused (returns false, nothing runs).
// - take() and the destructor wait for the work to end (ask it to stop first: the caller's own flag).
#pragma once

#include <atomic>
#include <functional>
#include <memory>

namespace meshedit {

class BackgroundWork {
 public:
  BackgroundWork();
  ~BackgroundWork();
  BackgroundWork(const BackgroundWork&) = delete;
  BackgroundWork& operator=(const BackgroundWork&) = delete;

  // Whether this host runs the work on a thread of its own (false: start() returns when the work is done).
  static bool threaded();
  bool start(std::function<void()> work);
  bool busy() const { return busy_; }
  bool done() const { return done_.load(std::memory_order_acquire); }
  // Waits for the work and ends busy(); a no-op when nothing was started.
  void take();

 private:
  struct Thread;
  std::unique_ptr<Thread> thread_;
  bool busy_ = false;
  std::atomic<bool> done_{false};
};

}  // namespace meshedit
