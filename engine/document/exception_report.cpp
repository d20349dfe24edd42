// Exceptions as status-line Errors (see exception_report.h).
#include "document/exception_report.h"

#include <new>
#include <string>

#include "core/translation.h"

namespace meshedit {
namespace {

bool is_out_of_memory(const std::exception& error) { return dynamic_cast<const std::bad_alloc*>(&error) != nullptr; }

}  // namespace

void report_exception(MeshDocument& doc, const std::exception& error) noexcept {
  if (is_out_of_memory(error)) {
    set_memory_ran_out_message(doc, Severity::Error);
    return;
  }
  set_message_noexcept(doc, Severity::Error, [&] { return std::string(error.what()); });
}

void report_escaped_exception(MeshDocument& doc, const std::exception& error) noexcept {
  const bool out_of_memory = is_out_of_memory(error);
  set_message_noexcept(doc, Severity::Error, [&] {
    return out_of_memory ? std::string(tr("memory ran out; the last action did not finish"))
                         : tr_format("the last action failed: {error}", {{"error", error.what()}});
  });
}

}  // namespace meshedit
