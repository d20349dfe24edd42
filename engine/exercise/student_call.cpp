// One call of a student's function on plain values (see student_call.h).
#include "exercise/student_call.h"

#include <exception>
#include <new>

namespace meshedit {
namespace {

// `what()` of an exception that should not have come, or out_of_memory when even that cannot be kept.
void keep_thrown(StudentCallResult& result, const std::exception& e) noexcept {
  try {
    result.thrown = e.what();
  } catch (const std::bad_alloc&) {
    result.out_of_memory = true;
  }
}

}  // namespace

StudentSource read_student_source(const std::filesystem::path& file) {
  std::optional<std::string> text = read_lua_file(file);
  if (!text) throw ScriptError("cannot open " + file.string());
  return {file.filename().string(), std::move(*text)};
}

StudentCallResult run_student_call_on(StudentCode& code, const StudentCall& call,
                                      const std::atomic<bool>* stop) noexcept {
  StudentCallResult result;
  LuaRuntime& runtime = code.runtime();
  runtime.set_limits(call.limits);
  runtime.set_stop_request(stop);
  try {
    result.outcome = code.run(call.exercise, call.input, call.options);
  } catch (const std::bad_alloc&) {
    result.out_of_memory = true;
  } catch (const std::exception& e) {  // StudentCode::run promises not to throw
    keep_thrown(result, e);
  }
  runtime.set_stop_request(nullptr);
  return result;
}

StudentCallResult run_student_call(const StudentCall& call, const std::atomic<bool>* stop) noexcept {
  StudentCallResult result;
  try {
    StudentCode code(call.limits);
    code.runtime().set_stop_request(stop);
    try {
      for (const StudentSource& file : call.files) code.load_text(file.text, file.name);
    } catch (const ScriptError& error) {  // its own file:line
      result.load_error = error.what();
      return result;
    }
    return run_student_call_on(code, call, stop);
  } catch (const std::bad_alloc&) {
    result.out_of_memory = true;
  } catch (const std::exception& e) {
    keep_thrown(result, e);
  }
  return result;
}

}  // namespace meshedit
