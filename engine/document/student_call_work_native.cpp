// StudentCallWork in this process: the call on BackgroundWork's thread (see student_call_work.h).
#include <atomic>
#include <utility>

#include "document/background_work.h"
#include "document/student_call_work.h"

namespace meshedit {

struct StudentCallWork::Host {
  StudentCall call;
  std::unique_ptr<StudentCode> code;
  std::atomic<bool> stop{false};  // read by the code's hook
  StudentCallResult result;       // written by the call's thread, read once it has ended
  BackgroundWork work;            // last: destroyed first, it waits for the thread that uses the rest

  void run() noexcept { result = code ? run_student_call_on(*code, call, &stop) : run_student_call(call, &stop); }
};

StudentCallWork::StudentCallWork() : host_(std::make_unique<Host>()) {}

StudentCallWork::~StudentCallWork() {
  stop();
  host_->work.take();
}

bool StudentCallWork::off_the_callers_thread() { return BackgroundWork::threaded(); }

bool StudentCallWork::start(StudentCall call, std::unique_ptr<StudentCode> code) {
  if (host_->work.busy()) return false;
  host_->call = std::move(call);
  host_->code = std::move(code);
  host_->stop.store(false);
  host_->result = StudentCallResult{};
  Host* host = host_.get();
  return host_->work.start([host] { host->run(); });
}

bool StudentCallWork::busy() const { return host_->work.busy(); }

bool StudentCallWork::done() const { return host_->work.busy() && host_->work.done(); }

void StudentCallWork::stop() { host_->stop.store(true); }

StudentCallResult StudentCallWork::take() {
  host_->work.take();
  return std::move(host_->result);
}

std::unique_ptr<StudentCode> StudentCallWork::take_code() { return std::move(host_->code); }

}  // namespace meshedit
