// Writing a test's feedback as text and as Markdown (see test_feedback.h).
#include "grade/test_feedback.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "core/translation.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The length of an element id with its fields at `i` ("h12", "v3.halfedge", "h0.twin.next"), or 0.
size_t id_length(const std::string& s, size_t i) {
  if (i > 0 && word_char(s[i - 1])) return 0;
  if (std::string("vehfb").find(s[i]) == std::string::npos || i + 1 >= s.size() || !digit(s[i + 1])) return 0;
  size_t j = i + 1;
  while (j < s.size() && digit(s[j])) ++j;
  while (j + 1 < s.size() && s[j] == '.' && std::islower(static_cast<unsigned char>(s[j + 1]))) {
    size_t k = j + 1;
    while (k < s.size() && (std::islower(static_cast<unsigned char>(s[k])) || s[k] == '_')) ++k;
    j = k;
  }
  return j < s.size() && word_char(s[j]) ? 0 : j - i;
}

// One line of plain text as Markdown: ids as code, what a message already quotes in backticks as code, the characters
// Markdown or HTML would read escaped.
std::string markdown_inline(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size();) {
    if (const size_t close = s.find('`', i + 1); s[i] == '`' && close != std::string::npos) {
      out += s.substr(i, close + 1 - i);
      i = close + 1;
      continue;
    }
    if (const size_t n = id_length(s, i); n > 0) {
      out += "`" + s.substr(i, n) + "`";
      i += n;
      continue;
    }
    if (std::string("\\`*_[]<>#|~&!").find(s[i]) != std::string::npos) out += '\\';
    out += s[i++];
  }
  return out;
}

// A fenced block holding `text` whatever it holds: the fence is longer than any run of backticks inside.
std::string fenced(const std::string& text) {
  size_t longest = 0, run = 0;
  for (char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(std::max<size_t>(3, longest + 1), '`');
  return fence + "text\n" + text + (text.empty() || text.back() == '\n' ? "" : "\n") + fence + "\n";
}

// The full-width colon and semicolon a Chinese text puts where English has ": " and "; " (UTF-8).
constexpr const char* kWideColon = "\xEF\xBC\x9A";
constexpr const char* kWideSemicolon = "\xEF\xBC\x9B";

// "**Timed out:** the rest": the label before the first ": " (or a translation's full-width colon) in bold.
std::string bold_label(const std::string& line) {
  const size_t colon = line.find(": "), wide = line.find(kWideColon);
  if (wide < colon) {
    const size_t after = wide + std::char_traits<char>::length(kWideColon);
    return "**" + markdown_inline(line.substr(0, after)) + "** " + markdown_inline(line.substr(after));
  }
  if (colon == std::string::npos) return markdown_inline(line);
  return "**" + markdown_inline(line.substr(0, colon + 1)) + "** " + markdown_inline(line.substr(colon + 2));
}

std::string failure_markdown(const CheckResult& check) {
  const std::string& m = check.message;
  const size_t head = check.headline > 0 && check.headline < m.size() ? check.headline : m.size();
  std::string out = "- " + markdown_inline(m.substr(0, head)) + "\n";
  std::string rest = m.substr(head);
  if (rest.rfind("; ", 0) == 0) rest.erase(0, 2);
  else if (rest.rfind(kWideSemicolon, 0) == 0) rest.erase(0, std::char_traits<char>::length(kWideSemicolon));
  if (!rest.empty()) {
    out += "\n  <details><summary>" + std::string(tr("the other differences")) + "</summary>\n\n  " +
           markdown_inline(rest) + "\n\n  </details>\n";
  }
  return out;
}

// "... and 3 more failed checks".
std::string more_failed_checks(size_t n) {
  const MessageParts parts = {{"count", std::to_string(n)}};
  return n == 1 ? tr_format("... and {count} more failed check", parts)
                : tr_format("... and {count} more failed checks", parts);
}

}  // namespace

std::string feedback_text(const TestFeedback& f) {
  std::ostringstream out;
  if (!f.stopped.empty()) out << f.stopped << "\n";
  if (!f.hint.empty()) out << f.hint << "\n";
  for (const CheckResult& check : f.failures) {
    out << tr_format("FAILED: {message}", {{"message", check.message}}) << "\n";
  }
  if (f.more_failures > 0) out << more_failed_checks(f.more_failures) << "\n";
  if (!f.tally.empty()) out << f.tally << "\n";
  if (!f.extra_credit.empty()) out << f.extra_credit << "\n";
  if (!f.printed.empty()) out << "\n" << tr("Your code printed:") << "\n" << f.printed;
  return out.str();
}

std::string feedback_markdown(const TestFeedback& f) {
  std::ostringstream out;
  if (!f.stopped.empty()) out << bold_label(f.stopped) << "\n\n";
  if (!f.hint.empty()) out << markdown_inline(f.hint) << "\n\n";
  if (!f.failures.empty()) {
    out << "**" << tr("Failed:") << "**\n\n";
    for (const CheckResult& check : f.failures) out << failure_markdown(check);
    if (f.more_failures > 0) out << "- " << markdown_inline(more_failed_checks(f.more_failures)) << "\n";
    out << "\n";
  }
  if (!f.tally.empty()) out << markdown_inline(f.tally) << "\n\n";
  if (!f.extra_credit.empty()) out << markdown_inline(f.extra_credit) << "\n\n";
  if (!f.printed.empty()) out << tr("Your code printed:") << "\n\n" << fenced(f.printed);
  std::string text = out.str();
  while (text.size() >= 2 && text.compare(text.size() - 2, 2, "\n\n") == 0) text.pop_back();
  return text;
}

std::string markdown_paragraphs(const std::string& text) {
  std::istringstream lines(text);
  std::string line, out;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    out += (out.empty() ? "" : "\n\n") + markdown_inline(line);
  }
  return out.empty() ? out : out + "\n";
}

}  // namespace meshedit
