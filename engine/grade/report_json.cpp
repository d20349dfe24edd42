// The grader's JSON for test runs and check reports (see report_json.h).
#include "grade/report_json.h"

#include <nlohmann/json.hpp>

#include "grade/submission.h"

namespace meshedit {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "meshedit check report";
constexpr int kVersion = 1;

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

RunEnd end_from_name(const std::string& name) {
  for (RunEnd e :
       {RunEnd::Completed, RunEnd::Error, RunEnd::LoadError, RunEnd::Timeout, RunEnd::Memory, RunEnd::Crash}) {
    if (name == run_end_name(e)) return e;
  }
  throw GradeError("unknown end '" + name + "' in a test report");
}

json case_json(const FailingCase& c) {
  return {{"exercise", c.exercise}, {"input", c.input}, {"mesh", c.mesh}, {"element", c.element}, {"mine", c.mine}};
}

FailingCase case_from(const json& j) {
  FailingCase c;
  c.exercise = j.at("exercise").get<std::string>();
  c.input = j.at("input").get<std::string>();
  c.mesh = j.at("mesh").get<std::string>();
  c.element = j.at("element").get<std::string>();
  c.mine = j.at("mine").get<std::string>();
  return c;
}

void put_case(json& j, const std::optional<FailingCase>& c) {
  if (c) j["failing_case"] = case_json(*c);
}

std::optional<FailingCase> case_at(const json& j) {
  if (!j.contains("failing_case")) return std::nullopt;
  return case_from(j.at("failing_case"));
}

json test_json(const TestResult& t) {
  json j = {{"number", t.number},
            {"name", t.name},
            {"visibility", t.visibility},
            {"tags", t.tags},
            {"score", t.score},
            {"max_score", t.max_score},
            {"extra_points", t.extra_points},
            {"passed", t.passed},
            {"end", run_end_name(t.end)},
            {"failure", t.failure},
            {"output", t.output},
            {"output_markdown", t.output_markdown},
            {"seconds", t.seconds}};
  put_case(j, t.failing_case);
  return j;
}

TestResult test_from(const json& j) {
  TestResult t;
  t.number = j.at("number").get<std::string>();
  t.name = j.at("name").get<std::string>();
  t.visibility = j.at("visibility").get<std::string>();
  t.tags = j.at("tags").get<std::vector<std::string>>();
  t.score = j.at("score").get<double>();
  t.max_score = j.at("max_score").get<double>();
  t.extra_points = j.at("extra_points").get<double>();
  t.passed = j.at("passed").get<bool>();
  t.end = end_from_name(j.at("end").get<std::string>());
  t.failure = j.at("failure").get<std::string>();
  t.output = j.at("output").get<std::string>();
  t.output_markdown = j.at("output_markdown").get<std::string>();
  t.seconds = j.at("seconds").get<double>();
  t.failing_case = case_at(j);
  return t;
}

}  // namespace

std::string encode_test_run(const TestRun& run) {
  json j;
  j["checks"] = json::array();
  for (const auto& c : run.checks) {
    json check = {{"passed", c.passed}, {"message", c.message}, {"headline", c.headline}};
    put_case(check, c.failing_case);
    j["checks"].push_back(std::move(check));
  }
  if (run.fraction) j["fraction"] = *run.fraction;
  j["end"] = run_end_name(run.end);
  j["error"] = run.error;
  j["output"] = run.output;
  j["output_truncated"] = run.output_truncated;
  return dump(j);
}

TestRun decode_test_run(const std::string& text) {
  TestRun run;
  try {
    const json j = json::parse(text);
    for (const auto& c : j.at("checks")) {
      run.checks.push_back(
          {c.at("passed").get<bool>(), c.at("message").get<std::string>(), c.at("headline").get<size_t>(), case_at(c)});
    }
    if (j.contains("fraction")) run.fraction = j.at("fraction").get<double>();
    run.end = end_from_name(j.at("end").get<std::string>());
    run.error = j.at("error").get<std::string>();
    run.output = j.at("output").get<std::string>();
    run.output_truncated = j.at("output_truncated").get<bool>();
  } catch (const json::exception& e) {
    throw GradeError(std::string("malformed test report: ") + e.what());
  }
  return run;
}

std::string encode_grade_report(const GradeReport& report) {
  json j = {{"format", kFormat},
            {"version", kVersion},
            {"suite", report.suite_name},
            {"score", report.score},
            {"max_score", report.max_score},
            {"extra_points", report.extra_points},
            {"execution_time", report.execution_time},
            {"output", report.output}};
  j["not_shown"] = json::array();
  for (const NotShown& n : report.not_shown) {
    j["not_shown"].push_back({{"visibility", n.visibility}, {"tests", n.tests}, {"points", n.points}});
  }
  j["tests"] = json::array();
  for (const TestResult& t : report.tests) j["tests"].push_back(test_json(t));
  return dump(j) + "\n";
}

GradeReport decode_grade_report(const std::string& text) {
  GradeReport report;
  try {
    const json j = json::parse(text);
    if (!j.is_object() || j.value("format", std::string()) != kFormat) {
      throw GradeError("not a MeshEdit check report (no \"format\": \"meshedit check report\")");
    }
    if (const int version = j.at("version").get<int>(); version != kVersion) {
      throw GradeError("a check report of version " + std::to_string(version) + "; this MeshEdit reads version " +
                       std::to_string(kVersion));
    }
    report.suite_name = j.at("suite").get<std::string>();
    report.score = j.at("score").get<double>();
    report.max_score = j.at("max_score").get<double>();
    report.extra_points = j.at("extra_points").get<double>();
    report.execution_time = j.at("execution_time").get<double>();
    report.output = j.at("output").get<std::string>();
    for (const auto& n : j.at("not_shown")) {
      report.not_shown.push_back(
          {n.at("visibility").get<std::string>(), n.at("tests").get<size_t>(), n.at("points").get<double>()});
    }
    for (const auto& t : j.at("tests")) report.tests.push_back(test_from(t));
  } catch (const json::exception& e) {
    throw GradeError(std::string("malformed check report: ") + e.what());
  }
  return report;
}

}  // namespace meshedit
