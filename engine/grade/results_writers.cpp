// Gradescope JSON, JUnit XML, TAP and the text report (see results_writers.h).
#include "grade/results_writers.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/value_format.h"
#include "grade/submission.h"
#include "grade/test_feedback.h"

namespace meshedit {
namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // XML 1.0 forbids most control characters, even escaped.
        if (c < 0x20 && c != '\n' && c != '\t' && c != '\r') out += "?";
        else out += static_cast<char>(c);
    }
  }
  return out;
}

// Valid UTF-8 (invalid bytes replaced), as JSON will hold it; XML and TAP use the same text.
std::string clean_utf8(const std::string& s) {
  const std::string dumped = nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return nlohmann::json::parse(dumped).get<std::string>();
}

std::string number(double x) { return format_number(x); }

std::string one_line(const std::string& s) {
  std::string out = s.substr(0, s.find('\n'));
  return out.size() > 200 ? out.substr(0, 200) + "..." : out;
}

// " (extra credit included: up to 2 more)", or "" for a suite without extra credit.
std::string extra_credit_note(const GradeReport& report) {
  if (report.extra_points <= 0) return "";
  return " (extra credit included: up to " + number(report.extra_points) + " more)";
}

}  // namespace

std::string summary_line(const GradeReport& report) {
  return std::to_string(report.passed()) + " passed, " + std::to_string(report.failed()) + " failed";
}

std::string gradescope_json(const GradeReport& report) {
  using nlohmann::json;
  json j;
  j["score"] = report.score;
  j["max_score"] = report.max_score;
  j["execution_time"] = static_cast<long>(std::ceil(report.execution_time));
  j["output"] = markdown_paragraphs(report.output);
  j["output_format"] = "md";
  j["test_output_format"] = "md";
  j["visibility"] = "visible";
  j["stdout_visibility"] = "hidden";
  j["extra_data"] = {{"grader", "meshedit grade"}, {"suite", report.suite_name}};
  j["tests"] = json::array();
  for (const auto& t : report.tests) {
    json test = {{"number", t.number},
                 {"name", t.name},
                 {"score", t.score},
                 {"max_score", t.max_score},
                 {"status", t.passed ? "passed" : "failed"},
                 {"output", t.output_markdown},
                 {"visibility", t.visibility}};
    if (!t.tags.empty()) test["tags"] = t.tags;
    j["tests"].push_back(std::move(test));
  }
  return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

std::string junit_xml(const GradeReport& report) {
  size_t failures = 0, errors = 0;
  for (const auto& t : report.tests) {
    if (t.passed) continue;
    if (t.end == RunEnd::Completed) ++failures;
    else ++errors;
  }
  const std::string suite = xml_escape(clean_utf8(report.suite_name));
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x << "<testsuites name=\"" << suite << "\" tests=\"" << report.tests.size() << "\" failures=\"" << failures
    << "\" errors=\"" << errors << "\" time=\"" << number(report.execution_time) << "\">\n";
  x << "  <testsuite name=\"" << suite << "\" tests=\"" << report.tests.size() << "\" failures=\"" << failures
    << "\" errors=\"" << errors << "\" skipped=\"0\" time=\"" << number(report.execution_time) << "\">\n";
  x << "    <properties>\n      <property name=\"score\" value=\"" << number(report.score) << "\"/>\n"
    << "      <property name=\"max_score\" value=\"" << number(report.max_score) << "\"/>\n    </properties>\n";
  for (const auto& t : report.tests) {
    x << "    <testcase classname=\"" << suite << "\" name=\"" << xml_escape(clean_utf8(t.number + " " + t.name))
      << "\" time=\"" << number(t.seconds) << "\">\n";
    x << "      <properties>\n        <property name=\"score\" value=\"" << number(t.score) << "\"/>\n"
      << "        <property name=\"max_score\" value=\"" << number(t.max_score) << "\"/>\n      </properties>\n";
    if (!t.passed) {
      const bool error = t.end != RunEnd::Completed;
      x << "      <" << (error ? "error" : "failure") << " message=\"" << xml_escape(clean_utf8(one_line(t.failure)))
        << "\" type=\"" << run_end_name(t.end) << "\">" << xml_escape(clean_utf8(t.output)) << "</"
        << (error ? "error" : "failure") << ">\n";
    }
    x << "    </testcase>\n";
  }
  x << "  </testsuite>\n</testsuites>\n";
  return x.str();
}

std::string tap_text(const GradeReport& report) {
  std::ostringstream t;
  t << "TAP version 14\n1.." << report.tests.size() << "\n";
  for (size_t i = 0; i < report.tests.size(); ++i) {
    const TestResult& r = report.tests[i];
    std::string name = clean_utf8(r.number + " " + r.name);
    for (char& c : name) {
      if (c == '#' || c == '\n') c = ' ';  // '#' would start a directive
    }
    t << (r.passed ? "ok " : "not ok ") << (i + 1) << " - " << name << "\n";
    if (!r.passed) {
      const nlohmann::json message = clean_utf8(one_line(r.failure));
      t << "  ---\n  message: " << message.dump() << "\n  severity: " << (r.end == RunEnd::Completed ? "fail" : "error")
        << "\n  score: " << number(r.score) << "\n  max_score: " << number(r.max_score) << "\n  ...\n";
    }
  }
  t << "# score " << number(report.score) << " / " << number(report.max_score) << extra_credit_note(report) << "\n";
  t << "# " << summary_line(report) << "\n";
  return t.str();
}

std::string points_text(const TestResult& test) {
  if (test.extra_points > 0) return "+" + number(test.score) + " of " + number(test.extra_points);
  return number(test.score) + "/" + number(test.max_score);
}

std::string score_line(const GradeReport& report) {
  return "Score: " + number(report.score) + " / " + number(report.max_score) + extra_credit_note(report);
}

std::string text_report(const GradeReport& report) {
  std::ostringstream s;
  s << report.output << "\n";
  for (const auto& t : report.tests) {
    s << (t.passed ? "PASS " : "FAIL ") << t.number << " " << t.name << "  " << points_text(t) << "\n";
    if (!t.passed) {
      std::istringstream lines(t.output);
      std::string line;
      while (std::getline(lines, line)) s << "    " << line << "\n";
    }
  }
  s << "\n" << score_line(report) << "\n";
  s << summary_line(report) << "\n";
  return s.str();
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::path folder = path.parent_path();
  std::error_code ec;
  if (!folder.empty()) std::filesystem::create_directories(folder, ec);
  const std::filesystem::path temporary = path.string() + ".tmp" + std::to_string(static_cast<long>(getpid()));
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw GradeError("cannot write " + path.string());
    out << text;
    out.flush();
    if (!out) {
      std::filesystem::remove(temporary, ec);
      throw GradeError("cannot write " + path.string());
    }
  }
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw GradeError("cannot write " + path.string());
  }
}

}  // namespace meshedit
