// A student call and its result as CBOR, both ways (see student_call_text.h).
#include "exercise/student_call_text.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>

#include "exercise/cbor_values.h"
#include "exercise/exercise_registry.h"

namespace meshedit {
namespace {

using nlohmann::json;

constexpr const char* kCallFormat = "meshedit student call 1";
constexpr const char* kResultFormat = "meshedit student call result 1";

using cbor::element_from;
using cbor::element_json;
using cbor::mesh_from;
using cbor::mesh_json;
using cbor::point_from;
using cbor::point_json;
using cbor::points_from;
using cbor::points_json;

json value_json(const ExerciseValue& value) {
  json items = json::array();
  for (const ExerciseValue& item : value.items) items.push_back(value_json(item));
  return {{"kind", static_cast<int>(value.kind)},
          {"number", value.number},
          {"point", point_json(value.point)},
          {"items", std::move(items)},
          {"other", value.other}};
}

ExerciseValue value_from(const json& j) {
  ExerciseValue value;
  const int kind = j.at("kind").get<int>();
  if (kind < 0 || kind > static_cast<int>(ExerciseValue::Kind::Other)) throw std::runtime_error("a value of no kind");
  value.kind = static_cast<ExerciseValue::Kind>(kind);
  value.number = j.at("number").get<double>();
  value.point = point_from(j.at("point"));
  for (const json& item : j.at("items")) value.items.push_back(value_from(item));
  value.other = j.at("other").get<std::string>();
  return value;
}

json values_json(const std::vector<ExerciseValue>& values) {
  json j = json::array();
  for (const ExerciseValue& value : values) j.push_back(value_json(value));
  return j;
}

std::vector<ExerciseValue> values_from(const json& j) {
  std::vector<ExerciseValue> values;
  for (const json& value : j) values.push_back(value_from(value));
  return values;
}

json input_json(const ExerciseInput& input) {
  const std::vector<glm::dvec3> patch(input.patch.points.begin(), input.patch.points.end());
  return {{"points", points_json(input.points)},
          {"t", input.t},
          {"patch", points_json(patch)},
          {"u", input.u},
          {"v", input.v},
          {"mesh", mesh_json(input.mesh.get())},
          {"element", element_json(input.element)},
          {"args", values_json(input.args)}};
}

ExerciseInput input_from(const json& j) {
  ExerciseInput input;
  input.points = points_from(j.at("points"));
  input.t = j.at("t").get<double>();
  const std::vector<glm::dvec3> patch = points_from(j.at("patch"));
  if (patch.size() != input.patch.points.size()) throw std::runtime_error("a patch is not 16 points");
  std::copy(patch.begin(), patch.end(), input.patch.points.begin());
  input.u = j.at("u").get<double>();
  input.v = j.at("v").get<double>();
  input.mesh = mesh_from(j.at("mesh"), "the call's input");
  input.element = element_from(j.at("element"));
  input.args = values_from(j.at("args"));
  return input;
}

json edit_value_json(const EditValue& value) {
  return {{"element", element_json(value.element)}, {"position", point_json(value.position)}};
}

EditValue edit_value_from(const json& j) { return {element_from(j.at("element")), point_from(j.at("position"))}; }

json edit_json(const RecordedEdit& edit) {
  return {{"what", static_cast<int>(edit.what)},
          {"element", element_json(edit.element)},
          {"field", edit.field},
          {"before", edit_value_json(edit.before)},
          {"value", edit_value_json(edit.value)},
          {"state", mesh_json(edit.state.get())},
          {"where", edit.where}};
}

RecordedEdit edit_from(const json& j) {
  RecordedEdit edit;
  const int what = j.at("what").get<int>();
  if (what < 0 || what > static_cast<int>(EditKind::Operation)) throw std::runtime_error("an edit of no kind");
  edit.what = static_cast<EditKind>(what);
  edit.element = element_from(j.at("element"));
  edit.field = j.at("field").get<std::string>();
  edit.before = edit_value_from(j.at("before"));
  edit.value = edit_value_from(j.at("value"));
  edit.state = mesh_from(j.at("state"), "a recorded state");
  edit.where = j.at("where").get<std::string>();
  return edit;
}

json outcome_json(const ExerciseOutcome& out) {
  json edits = json::array();
  for (const RecordedEdit& edit : out.edits) edits.push_back(edit_json(edit));
  json touched = nullptr;
  if (out.touched) {
    touched = {{"elements", out.touched->elements},
               {"written", out.touched->written},
               {"whole_mesh_call", out.touched->whole_mesh_call}};
  }
  return {{"ran", out.ran},
          {"error", out.error},
          {"out_of_memory", out.out_of_memory},
          {"limit", static_cast<int>(out.limit)},
          {"returned", out.returned},
          {"points", points_json(out.points)},
          {"value", value_json(out.value)},
          {"mesh", mesh_json(out.mesh.get())},
          {"element", element_json(out.element)},
          {"refused", out.refused},
          {"validated", out.validation.has_value()},
          {"edits", std::move(edits)},
          {"touched", std::move(touched)},
          {"output", out.output}};
}

ExerciseOutcome outcome_from(const json& j) {
  ExerciseOutcome out;
  out.ran = j.at("ran").get<bool>();
  out.error = j.at("error").get<std::string>();
  out.out_of_memory = j.at("out_of_memory").get<bool>();
  const int limit = j.at("limit").get<int>();
  if (limit < 0 || limit > static_cast<int>(ScriptError::Limit::Stopped)) throw std::runtime_error("a limit of none");
  out.limit = static_cast<ScriptError::Limit>(limit);
  out.returned = j.at("returned").get<std::string>();
  out.points = points_from(j.at("points"));
  out.value = value_from(j.at("value"));
  out.mesh = mesh_from(j.at("mesh"), "the call's mesh");
  out.element = element_from(j.at("element"));
  out.refused = j.at("refused").get<std::string>();
  if (j.at("validated").get<bool>() && out.mesh) out.validation = validate(*out.mesh);
  for (const json& edit : j.at("edits")) out.edits.push_back(edit_from(edit));
  if (const json& touched = j.at("touched"); !touched.is_null()) {
    out.touched = TouchCount{touched.at("elements").get<size_t>(), touched.at("written").get<size_t>(),
                             touched.at("whole_mesh_call").get<std::string>()};
  }
  out.output = j.at("output").get<std::vector<std::string>>();
  return out;
}

}  // namespace

std::vector<uint8_t> encode_student_call(const StudentCall& call) {
  json files = json::array();
  for (const StudentSource& file : call.files) files.push_back({{"name", file.name}, {"text", file.text}});
  const json j = {{"format", kCallFormat},
                  {"exercise", call.exercise.info().name},
                  {"input", input_json(call.input)},
                  {"record_edits", call.options.record_edits},
                  {"max_edits", call.options.max_edits},
                  {"instructions", call.limits.instructions},
                  {"memory_bytes", call.limits.memory_bytes},
                  {"wall_seconds", call.limits.wall_seconds},
                  {"files", std::move(files)}};
  return json::to_cbor(j);
}

StudentCall decode_student_call(std::span<const uint8_t> bytes) {
  return cbor::read_cbor_text(bytes, kCallFormat, "student call", [](const json& j) {
    StudentCall call;
    const std::string name = j.at("exercise").get<std::string>();
    const std::optional<Exercise> exercise = exercise_registry().find(name);
    if (!exercise) throw std::runtime_error(exercise_registry().unknown_name_error(name));
    call.exercise = *exercise;
    call.input = input_from(j.at("input"));
    call.options.record_edits = j.at("record_edits").get<bool>();
    call.options.max_edits = j.at("max_edits").get<size_t>();
    call.limits.instructions = j.at("instructions").get<uint64_t>();
    call.limits.memory_bytes = j.at("memory_bytes").get<size_t>();
    call.limits.wall_seconds = j.at("wall_seconds").get<double>();
    for (const json& file : j.at("files")) {
      call.files.push_back({file.at("name").get<std::string>(), file.at("text").get<std::string>()});
    }
    return call;
  });
}

std::vector<uint8_t> encode_student_call_result(const StudentCallResult& result) {
  const json j = {{"format", kResultFormat},
                  {"outcome", outcome_json(result.outcome)},
                  {"load_error", result.load_error},
                  {"out_of_memory", result.out_of_memory},
                  {"thrown", result.thrown}};
  return json::to_cbor(j);
}

StudentCallResult decode_student_call_result(std::span<const uint8_t> bytes) {
  return cbor::read_cbor_text(bytes, kResultFormat, "student call's result", [](const json& j) {
    StudentCallResult result;
    result.outcome = outcome_from(j.at("outcome"));
    result.load_error = j.at("load_error").get<std::string>();
    result.out_of_memory = j.at("out_of_memory").get<bool>();
    result.thrown = j.at("thrown").get<std::string>();
    return result;
  });
}

}  // namespace meshedit
