// Check and OpResult: how an operation says yes, or no and why.
//
// Every mesh operation comes as a pair `can_X(...) -> Check` and `X(...) -> OpResult<T>`; when the
// check fails the operation changes nothing, and `reason` is a sentence for the user that names the
// elements involved ("e5 is on the boundary (b0); only interior edges can be flipped").
#pragma once

#include <string>
#include <utility>

namespace meshedit {

struct Check {
  bool ok = true;
  std::string reason;  // empty when ok

  static Check yes() { return {}; }
  static Check no(std::string why) { return {false, std::move(why)}; }
  explicit operator bool() const { return ok; }
};

template <class T>
struct OpResult {
  Check check;
  T value{};  // meaningful only when check.ok

  bool ok() const { return check.ok; }
  explicit operator bool() const { return check.ok; }
};

}  // namespace meshedit
