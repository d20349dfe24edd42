// The class report: results files read, tests counted, mistakes grouped by kind, the page and the CSV (see
// class_report.h).
#include "grade/class_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <set>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/file_bytes.h"
#include "core/text_escapes.h"

namespace meshedit {
namespace {

constexpr int kBins = 10;  // the histograms' bars: tenths of the maximum

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Markdown's inline marks taken off: **bold**, `code`, backslash escapes.
std::string plain(const std::string& line) {
  std::string out;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size()) {
      out += line[++i];
    } else if (line[i] == '`') {
      continue;
    } else if (line.compare(i, 2, "**") == 0) {
      ++i;
    } else {
      out += line[i];
    }
  }
  return out;
}

std::string part_of(const std::string& number) {
  const size_t dot = number.find('.');
  return dot == std::string::npos ? number : number.substr(0, dot);
}

// An SVG bar chart of `counts` (kBins bars from 0 to `max`), `label` above it.
std::string histogram_svg(const std::vector<size_t>& counts, double max, const std::string& label) {
  const size_t highest = std::max<size_t>(1, *std::max_element(counts.begin(), counts.end()));
  constexpr int kWidth = 400, kHeight = 120, kBar = kWidth / kBins;
  std::ostringstream svg;
  svg << "<figure><svg width=\"" << kWidth << "\" height=\"" << kHeight + 34 << "\" role=\"img\" aria-label=\""
      << html_escaped(label) << "\">";
  for (int b = 0; b < kBins; ++b) {
    const int h = static_cast<int>(std::lround(double(counts[b]) / double(highest) * kHeight));
    svg << "<rect x=\"" << b * kBar + 1 << "\" y=\"" << kHeight - h << "\" width=\"" << kBar - 2 << "\" height=\"" << h
        << "\" fill=\"#4a7bd0\"><title>" << counts[b] << "</title></rect>";
    if (counts[b] > 0) {
      svg << "<text x=\"" << b * kBar + kBar / 2 << "\" y=\"" << kHeight - h - 2
          << "\" font-size=\"11\" text-anchor=\"middle\">" << counts[b] << "</text>";
    }
    svg << "<text x=\"" << b * kBar + kBar / 2 << "\" y=\"" << kHeight + 14
        << "\" font-size=\"10\" text-anchor=\"middle\">" << number_text(max * b / kBins) << "</text>";
  }
  svg << "<text x=\"0\" y=\"" << kHeight + 30 << "\" font-size=\"11\">score (out of " << number_text(max)
      << "), students per tenth</text></svg><figcaption>" << html_escaped(label) << "</figcaption></figure>\n";
  return svg.str();
}

std::vector<size_t> bins_of(const std::vector<double>& scores, double max) {
  std::vector<size_t> counts(kBins, 0);
  for (const double score : scores) {
    const int bin = max > 0.0 ? static_cast<int>(std::floor(score / max * kBins)) : 0;
    ++counts[static_cast<size_t>(std::clamp(bin, 0, kBins - 1))];
  }
  return counts;
}

}  // namespace

const char* test_outcome_name(TestOutcome outcome) {
  switch (outcome) {
    case TestOutcome::Passed: return "passed";
    case TestOutcome::Partly: return "partly passed";
    case TestOutcome::Failed: return "failed";
    case TestOutcome::TimedOut: return "timed out";
    case TestOutcome::Crashed: return "crashed";
  }
  return "failed";
}

TestOutcome test_outcome(const ClassTestResult& test) {
  const std::string first = diagnosis_of(test.output);
  if (first.starts_with("Timed out:")) return TestOutcome::TimedOut;
  if (first.starts_with("Crashed:")) return TestOutcome::Crashed;
  if (test.max_score <= 0.0) return test.score > 0.0 ? TestOutcome::Passed : TestOutcome::Failed;  // extra credit
  if (test.score >= test.max_score) return TestOutcome::Passed;
  return test.score > 0.0 ? TestOutcome::Partly : TestOutcome::Failed;
}

ClassResult read_class_result(const std::string& name, const std::string& text) {
  ClassResult result;
  result.name = name;
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    if (!j.is_object() || !j.contains("tests") || !j.at("tests").is_array()) {
      result.problem = "not a Gradescope results.json (no \"tests\" list)";
      return result;
    }
    double total = 0.0, max_total = 0.0;
    for (const nlohmann::json& t : j.at("tests")) {
      ClassTestResult test;
      test.number = t.value("number", "");
      test.name = t.value("name", "");
      test.score = t.value("score", 0.0);
      test.max_score = t.value("max_score", 0.0);
      test.output = t.value("output", "");
      total += test.score;
      max_total += test.max_score;
      result.tests.push_back(std::move(test));
    }
    result.score = j.contains("score") && j.at("score").is_number() ? j.at("score").get<double>() : total;
    result.max_score =
        j.contains("max_score") && j.at("max_score").is_number() ? j.at("max_score").get<double>() : max_total;
  } catch (const nlohmann::json::exception& e) {
    result = ClassResult{};
    result.name = name;
    result.problem = std::string("not JSON, or truncated (") + e.what() + ")";
  }
  return result;
}

ClassResult read_class_result_file(const std::filesystem::path& file) {
  const std::string name = file.filename() == "results.json" && file.has_parent_path()
                               ? file.parent_path().filename().string()
                               : file.stem().string();
  const FileBytes text = read_file_bytes(file, size_t(64) << 20);
  if (!text.ok()) {
    ClassResult unread;
    unread.name = name;
    unread.problem = file.string() + ": " + text.error;
    return unread;
  }
  ClassResult result = read_class_result(name, text.bytes);
  if (!result.problem.empty()) result.problem = file.string() + ": " + result.problem;
  return result;
}

std::vector<ClassResult> read_class_folder(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (std::filesystem::is_regular_file(entry.path() / "results.json", error))
      files.push_back(entry.path() / "results.json");
  }
  std::sort(files.begin(), files.end());
  std::vector<ClassResult> results;
  for (const std::filesystem::path& file : files) results.push_back(read_class_result_file(file));
  return results;
}

std::string diagnosis_of(const std::string& output) {
  std::istringstream lines(output);
  std::string first;
  bool failed_list = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line.starts_with("![")) continue;
    const std::string text = plain(line);
    if (text.starts_with("Failed:")) {
      failed_list = true;
      continue;
    }
    if (failed_list && text.starts_with("- ")) return text.substr(2);
    if (first.empty()) first = text;
    if (!failed_list) return first;
  }
  return first;
}

bool stopped_diagnosis(const std::string& diagnosis) {
  for (const char* label : {"Timed out: ", "Crashed: ", "Load error: ", "Out of memory: "}) {
    if (diagnosis.starts_with(label)) return true;
  }
  return false;
}

// Whether `prefix` (the text before a ": ") names what was checked or on which mesh ("flip_edge(e2) of a 1x1 grid",
// "bumpy icosahedron, vertex v0", "cube") rather than says the mistake ("the weights are swapped", "after your ...").
bool names_the_case(const std::string& prefix) {
  for (const char* sentence : {"your", " is ", " are ", " was ", " were "}) {
    if (prefix.find(sentence) != std::string::npos) return false;
  }
  const bool specific = prefix.find_first_of("0123456789(") != std::string::npos;
  return specific || std::count(prefix.begin(), prefix.end(), ' ') < 3;
}

std::string mistake_kind(const std::string& diagnosis) {
  std::string kind = diagnosis;
  for (int strip = 0; strip < 3 && !stopped_diagnosis(kind); ++strip) {
    const size_t colon = kind.find(": ");
    if (colon == std::string::npos || !names_the_case(kind.substr(0, colon))) break;
    kind = kind.substr(colon + 2);
  }
  static const std::regex kIds(R"(\b([hvefb])[0-9]+\b)");
  static const std::regex kNumbers(R"(-?\b[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?\b)");
  static const std::regex kIdRuns(R"(\b([hvefb])N((,? | and )[hvefb]N)+)");  // "v0 v2 v3", "f1, f2 and f5"
  kind = std::regex_replace(kind, kIds, "$1N");
  kind = std::regex_replace(kind, kNumbers, "N");
  kind = std::regex_replace(kind, kIdRuns, "$1N...");
  return kind;
}

ClassReport make_class_report(std::vector<ClassResult> results) {
  ClassReport report;
  report.results = std::move(results);
  std::map<std::string, size_t> test_index;
  std::map<std::string, size_t> mistake_index;
  std::set<std::string> parts;
  for (const ClassResult& result : report.results) {
    if (!result.problem.empty()) continue;
    report.max_score = std::max(report.max_score, result.max_score);
    for (const ClassTestResult& test : result.tests) {
      const std::string key = test.number + " " + test.name;
      auto [at, added] = test_index.emplace(key, report.tests.size());
      if (added) report.tests.push_back({test.number, test.name, test.max_score, {}});
      const TestOutcome outcome = test_outcome(test);
      ++report.tests[at->second].outcomes[outcome];
      if (!test.number.empty()) parts.insert(part_of(test.number));
      if (outcome == TestOutcome::Passed) continue;
      const std::string diagnosis = diagnosis_of(test.output);
      if (diagnosis.empty()) continue;
      if (stopped_diagnosis(diagnosis)) {
        if (report.stopped.empty() || report.stopped.back().student != result.name) {
          report.stopped.push_back({result.name, key, diagnosis, 0});
        }
        ++report.stopped.back().tests;
        continue;
      }
      const std::string kind = mistake_kind(diagnosis);
      auto [m, new_kind] = mistake_index.emplace(kind, report.mistakes.size());
      if (new_kind) report.mistakes.push_back({kind, diagnosis, {}, {}});
      ClassMistake& mistake = report.mistakes[m->second];
      if (std::find(mistake.tests.begin(), mistake.tests.end(), key) == mistake.tests.end())
        mistake.tests.push_back(key);
      if (std::find(mistake.students.begin(), mistake.students.end(), result.name) == mistake.students.end()) {
        mistake.students.push_back(result.name);
      }
    }
  }
  std::stable_sort(report.mistakes.begin(), report.mistakes.end(), [](const ClassMistake& a, const ClassMistake& b) {
    if (a.students.size() != b.students.size()) return a.students.size() > b.students.size();
    return a.kind < b.kind;
  });
  report.parts.assign(parts.begin(), parts.end());
  std::sort(report.parts.begin(), report.parts.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;  // "2" before "10"
  });
  return report;
}

std::string class_report_csv(const ClassReport& report) {
  std::ostringstream csv;
  csv << "student,score,max_score";
  for (const ClassTestSummary& test : report.tests)
    csv << "," << csv_field(test.number.empty() ? test.name : test.number);
  csv << ",problem\n";
  for (const ClassResult& result : report.results) {
    csv << csv_field(result.name) << ",";
    if (result.problem.empty()) csv << number_text(result.score) << "," << number_text(result.max_score);
    else csv << ",";
    for (const ClassTestSummary& test : report.tests) {
      csv << ",";
      for (const ClassTestResult& mine : result.tests) {
        if (mine.number == test.number && mine.name == test.name) {
          csv << number_text(mine.score);
          break;
        }
      }
    }
    csv << "," << csv_field(result.problem) << "\n";
  }
  return csv.str();
}

namespace {

// The histograms: the assignment's scores, then each part's.
std::string scores_html(const ClassReport& report, const std::vector<double>& scores) {
  std::string html =
      "<h2>Scores</h2>\n" + histogram_svg(bins_of(scores, report.max_score), report.max_score, "the assignment");
  for (const std::string& part : report.parts) {
    std::vector<double> part_scores;
    double part_max = 0.0;
    for (const ClassResult& result : report.results) {
      if (!result.problem.empty()) continue;
      double score = 0.0, max = 0.0;
      for (const ClassTestResult& test : result.tests) {
        if (part_of(test.number) != part) continue;
        score += test.score;
        max += test.max_score;
      }
      part_scores.push_back(score);
      part_max = std::max(part_max, max);
    }
    html += histogram_svg(bins_of(part_scores, part_max), part_max, "part " + part);
  }
  return html;
}

std::string mistakes_html(const ClassReport& report, size_t read) {
  std::ostringstream html;
  html << "<h2>The mistakes, most common first</h2>\n";
  if (report.mistakes.empty()) html << "<p>No test failed.</p>\n";
  html << "<ol>\n";
  for (const ClassMistake& mistake : report.mistakes) {
    const double share = read > 0 ? 100.0 * double(mistake.students.size()) / double(read) : 0.0;
    html << "<li><p><b>" << html_escaped(mistake.example) << "</b></p><p>" << mistake.students.size()
         << (mistake.students.size() == 1 ? " student" : " students") << " (" << std::lround(share) << "%): ";
    for (size_t i = 0; i < mistake.students.size(); ++i) html << (i ? ", " : "") << html_escaped(mistake.students[i]);
    html << "<br>in ";
    for (size_t i = 0; i < mistake.tests.size(); ++i) html << (i ? "; " : "") << html_escaped(mistake.tests[i]);
    html << "<br>kind: <code>" << html_escaped(mistake.kind) << "</code></p></li>\n";
  }
  html << "</ol>\n";
  return html.str();
}

std::string tests_html(const ClassReport& report) {
  std::ostringstream html;
  html << "<h2>Each test</h2>\n<table>\n<tr><th>test</th><th>points</th>";
  const TestOutcome outcomes[] = {TestOutcome::Passed, TestOutcome::Partly, TestOutcome::Failed, TestOutcome::TimedOut,
                                  TestOutcome::Crashed};
  for (const TestOutcome outcome : outcomes) html << "<th>" << test_outcome_name(outcome) << "</th>";
  html << "</tr>\n";
  for (const ClassTestSummary& test : report.tests) {
    html << "<tr><td>" << html_escaped(test.number + " " + test.name) << "</td><td class=\"n\">"
         << number_text(test.max_score) << "</td>";
    for (const TestOutcome outcome : outcomes) {
      const auto found = test.outcomes.find(outcome);
      html << "<td class=\"n\">" << (found == test.outcomes.end() ? 0 : found->second) << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</table>\n";
  return html.str();
}

// The students whose tests were stopped or did not load, and the files that could not be read.
std::string stopped_and_unread_html(const ClassReport& report) {
  std::ostringstream html;
  html << "<h2>Stopped or not loaded</h2>\n";
  if (report.stopped.empty()) html << "<p>No test was stopped, and every submission loaded.</p>\n";
  else html << "<ul>\n";
  for (const ClassStopped& stopped : report.stopped) {
    html << "<li><b>" << html_escaped(stopped.student) << "</b>: " << stopped.tests
         << (stopped.tests == 1 ? " test" : " tests") << ", the first " << html_escaped(stopped.test) << ": "
         << html_escaped(stopped.diagnosis) << "</li>\n";
  }
  if (!report.stopped.empty()) html << "</ul>\n";
  html << "<h2>Not read</h2>\n";
  bool none = true;
  for (const ClassResult& result : report.results) {
    if (result.problem.empty()) continue;
    if (none) html << "<ul>\n";
    none = false;
    html << "<li><b>" << html_escaped(result.name) << "</b>: <span class=\"problem\">" << html_escaped(result.problem)
         << "</span></li>\n";
  }
  html << (none ? "<p>Every results file was read.</p>\n" : "</ul>\n");
  return html.str();
}

}  // namespace

ClassChanges compare_class_reports(const ClassReport& before, const ClassReport& now) {
  ClassChanges changes;
  std::map<std::string, double> old_scores, new_scores;
  for (const ClassResult& r : before.results) {
    if (r.problem.empty()) old_scores[r.name] = r.score;
  }
  for (const ClassResult& r : now.results) {
    if (!r.problem.empty()) continue;
    new_scores[r.name] = r.score;
    const auto old = old_scores.find(r.name);
    if (old == old_scores.end()) changes.new_students.push_back(r.name);
    else if (r.score > old->second) changes.improved.push_back({r.name, old->second, r.score});
    else if (r.score < old->second) changes.worse.push_back({r.name, old->second, r.score});
  }
  for (const ClassResult& r : before.results) {
    if (r.problem.empty() && !new_scores.contains(r.name)) changes.gone_students.push_back(r.name);
  }
  const auto by_change = [](const ClassChanges::Score& a, const ClassChanges::Score& b) {
    return std::abs(a.now - a.before) > std::abs(b.now - b.before);
  };
  std::stable_sort(changes.improved.begin(), changes.improved.end(), by_change);
  std::stable_sort(changes.worse.begin(), changes.worse.end(), by_change);
  std::map<std::string, const ClassMistake*> old_kinds;
  for (const ClassMistake& m : before.mistakes) old_kinds[m.kind] = &m;
  for (const ClassMistake& m : now.mistakes) {
    const auto old = old_kinds.find(m.kind);
    const size_t was = old == old_kinds.end() ? 0 : old->second->students.size();
    const ClassChanges::Mistake change{m.example, was, m.students.size()};
    if (was == 0) changes.new_mistakes.push_back(change);
    else if (m.students.size() < was) changes.fewer.push_back(change);
    else if (m.students.size() > was) changes.more.push_back(change);
    if (old != old_kinds.end()) old_kinds.erase(old);
  }
  for (const ClassMistake& m : before.mistakes) {
    if (old_kinds.contains(m.kind)) changes.gone.push_back({m.example, m.students.size(), 0});
  }
  return changes;
}

namespace {

std::string changes_html(const ClassChanges& changes) {
  std::ostringstream html;
  html << "<h2>Since the earlier marks</h2>\n";
  const auto scores = [&](const char* title, const std::vector<ClassChanges::Score>& list) {
    if (list.empty()) return;
    html << "<p>" << title << ": ";
    for (size_t i = 0; i < list.size(); ++i) {
      html << (i ? ", " : "") << html_escaped(list[i].student) << " (" << number_text(list[i].before) << " to "
           << number_text(list[i].now) << ")";
    }
    html << "</p>\n";
  };
  scores("Improved", changes.improved);
  scores("Did worse", changes.worse);
  const auto names = [&](const char* title, const std::vector<std::string>& list) {
    if (list.empty()) return;
    html << "<p>" << title << ": ";
    for (size_t i = 0; i < list.size(); ++i) html << (i ? ", " : "") << html_escaped(list[i]);
    html << "</p>\n";
  };
  names("New in these marks", changes.new_students);
  names("Not in these marks", changes.gone_students);
  const auto mistakes = [&](const char* title, const std::vector<ClassChanges::Mistake>& list) {
    if (list.empty()) return;
    html << "<h3>" << title << "</h3>\n<ul>\n";
    for (const ClassChanges::Mistake& m : list) {
      html << "<li>" << html_escaped(m.example) << " (" << m.before << " to " << m.now << " students)</li>\n";
    }
    html << "</ul>\n";
  };
  mistakes("Mistakes that went away", changes.gone);
  mistakes("Mistakes fewer students make", changes.fewer);
  mistakes("Mistakes more students make", changes.more);
  mistakes("New mistakes", changes.new_mistakes);
  const bool nothing = changes.improved.empty() && changes.worse.empty() && changes.new_students.empty() &&
                       changes.gone_students.empty() && changes.gone.empty() && changes.fewer.empty() &&
                       changes.more.empty() && changes.new_mistakes.empty();
  if (nothing) html << "<p>Nothing changed: the same scores and the same mistakes.</p>\n";
  return html.str();
}

}  // namespace

std::string class_report_html(const ClassReport& report, const ClassChanges* changes) {
  size_t read = 0;
  std::vector<double> scores;
  for (const ClassResult& result : report.results) {
    if (!result.problem.empty()) continue;
    ++read;
    scores.push_back(result.score);
  }
  std::ostringstream html;
  html
      << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>The class at a glance</title>\n"
      << "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto;padding:0 1em;color:#222}"
      << "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 8px;text-align:left}"
      << "td.n{text-align:right}figure{display:inline-block;margin:0 1em 1em 0}figcaption{color:#444}"
      << "code{background:#f3f3f3}.problem{color:#a02020}</style>\n</head>\n<body>\n"
      << "<h1>The class at a glance</h1>\n<p>" << report.results.size() << " results files, " << read
      << " read; the most a student could score: " << number_text(report.max_score) << ".</p>\n"
      << (changes ? changes_html(*changes) : std::string()) << scores_html(report, scores)
      << mistakes_html(report, read) << tests_html(report) << stopped_and_unread_html(report) << "</body>\n</html>\n";
  return html.str();
}

}  // namespace meshedit
