// A student call run on plain values (student_call.h) and sent as bytes (student_call_text.h): the call runs the
// files' texts with their names in its errors, stops when asked, and its result after a trip through the bytes is the
// result itself: the same mesh record for record, the same edits, positions bit for bit (NaN too), the same
// validation; a file that is not UTF-8 goes byte for byte; bytes that are not a call, and an exercise the registry
// does not know, are errors that say so.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_records.h"
#include "core/primitives.h"
#include "exercise/student_call.h"
#include "exercise/student_call_text.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

std::shared_ptr<const HalfedgeMesh> cube() {
  return std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_cube()));
}

StudentSource solution(const char* file) {
  return read_student_source(testing::source_dir() / "tests" / "exercise" / "solutions" / file);
}

StudentCall flip_call(std::vector<StudentSource> files) {
  StudentCall call;
  call.exercise = Exercise::FlipEdge;
  call.input = ExerciseInput::edge(cube(), EdgeId(0));
  call.options.record_edits = true;
  call.files = std::move(files);
  return call;
}

StudentCallResult round_trip(const StudentCallResult& result) {
  return decode_student_call_result(encode_student_call_result(result));
}

TEST(StudentCall, RunsTheFilesTextsAndNamesThemInItsErrors) {
  const StudentCallResult flipped = run_student_call(flip_call({solution("flip.lua")}));
  ASSERT_TRUE(flipped.load_error.empty()) << flipped.load_error;
  ASSERT_TRUE(flipped.outcome.ran) << flipped.outcome.error;
  EXPECT_EQ(flipped.outcome.element, ElementRef(EdgeId(0)));
  ASSERT_TRUE(flipped.outcome.mesh);
  const HalfedgeMesh reference = [] {
    HalfedgeMesh mesh = *cube();
    EXPECT_TRUE(flip(mesh, EdgeId(0)).ok());  // the core's flip: the solution matches it pointer for pointer
    return mesh;
  }();
  EXPECT_TRUE(flipped.outcome.mesh->same_as(reference));
  EXPECT_FALSE(flipped.outcome.edits.empty());

  const StudentCallResult broken = run_student_call(flip_call({{"flip.lua", "function flip_edge(mesh, e)\n  x(\n"}}));
  EXPECT_EQ(broken.load_error.rfind("flip.lua:3:", 0), 0u) << broken.load_error;
  EXPECT_FALSE(broken.outcome.ran);

  const StudentCallResult failing =
      run_student_call(flip_call({{"flip.lua", "function flip_edge(mesh, e)\n  return e.nothing.twin\nend\n"}}));
  EXPECT_TRUE(failing.load_error.empty());
  EXPECT_EQ(failing.outcome.error.rfind("flip.lua:2:", 0), 0u) << failing.outcome.error;
}

TEST(StudentCall, AFileThatIsNotUTF8SaysSoInItsError) {
  const StudentCallResult utf16 = run_student_call(flip_call({{"flip.lua", std::string("\xFF\xFEr\0e\0t\0", 8)}}));
  EXPECT_NE(utf16.load_error.find("(flip.lua is UTF-16 text, which Lua cannot read: save it as UTF-8)"),
            std::string::npos)
      << utf16.load_error;
  const auto marked = testing::scratch_dir() / "flip.lua";
  std::ofstream(marked, std::ios::binary) << "\xEF\xBB\xBF" << solution("flip.lua").text;
  const StudentCallResult loaded = run_student_call(flip_call({read_student_source(marked)}));
  EXPECT_TRUE(loaded.load_error.empty()) << loaded.load_error;
  EXPECT_TRUE(loaded.outcome.ran) << loaded.outcome.error;
}

TEST(StudentCall, StopsAtItsNextLineWhenAsked) {
  const std::atomic<bool> stop{true};
  const StudentCallResult stopped =
      run_student_call(flip_call({{"flip.lua", "function flip_edge(mesh, e)\n  while true do end\nend\n"}}), &stop);
  EXPECT_EQ(stopped.outcome.limit, ScriptError::Limit::Stopped);
  EXPECT_NE(stopped.outcome.error.find("stopped: you pressed Stop"), std::string::npos) << stopped.outcome.error;
}

TEST(StudentCallText, ACallComesBackAsItWent) {
  StudentCall call = flip_call({solution("flip.lua"), {"notes.lua", std::string("-- caf\xE9 \xFF\n")}});
  call.limits.wall_seconds = 2.5;
  call.limits.instructions = 123456789;
  call.options.max_edits = 77;
  call.input.points = {{0.1, std::numeric_limits<double>::quiet_NaN(), -0.0}};
  call.input.args = {ExerciseValue::of_list({ExerciseValue::of_number(0.3), ExerciseValue::of_point({1, 2, 3})})};
  const StudentCall back = decode_student_call(encode_student_call(call));
  EXPECT_EQ(back.exercise, Exercise::FlipEdge);
  ASSERT_TRUE(back.input.mesh);
  EXPECT_TRUE(back.input.mesh->same_as(*call.input.mesh));
  EXPECT_EQ(back.input.element, call.input.element);
  ASSERT_EQ(back.files.size(), 2u);
  EXPECT_EQ(back.files[0].name, "flip.lua");
  EXPECT_EQ(back.files[0].text, call.files[0].text);
  EXPECT_EQ(back.files[1].text, call.files[1].text);  // not UTF-8: byte for byte
  EXPECT_EQ(back.limits.wall_seconds, 2.5);
  EXPECT_EQ(back.limits.instructions, 123456789u);
  EXPECT_EQ(back.limits.memory_bytes, call.limits.memory_bytes);
  EXPECT_TRUE(back.options.record_edits);
  EXPECT_EQ(back.options.max_edits, 77u);
  ASSERT_EQ(back.input.points.size(), 1u);
  EXPECT_EQ(back.input.points[0].x, 0.1);
  EXPECT_TRUE(std::isnan(back.input.points[0].y));
  EXPECT_TRUE(std::signbit(back.input.points[0].z));
  ASSERT_EQ(back.input.args.size(), 1u);
  EXPECT_EQ(value_text(back.input.args[0]), "{0.3, (1, 2, 3)}");
}

TEST(StudentCallText, AResultComesBackAsItWentEvenABrokenMesh) {
  // A flip that forgets the faces' halfedges: a mesh validate() finds wrong, kept record for record.
  std::string broken = solution("flip.lua").text;
  const std::string forgotten = "  f0.halfedge = h0\n";
  ASSERT_NE(broken.find(forgotten), std::string::npos);
  broken.replace(broken.find(forgotten), forgotten.size(), "  print('flipped', 1 / 0)\n");
  const StudentCallResult result = run_student_call(flip_call({{"flip.lua", broken}}));
  ASSERT_TRUE(result.outcome.mesh) << result.load_error << result.outcome.error;
  ASSERT_TRUE(result.outcome.validation);
  const StudentCallResult back = round_trip(result);
  ASSERT_TRUE(back.outcome.mesh);
  EXPECT_TRUE(back.outcome.mesh->same_as(*result.outcome.mesh));
  EXPECT_EQ(format_mesh_records(*back.outcome.mesh), format_mesh_records(*result.outcome.mesh));
  ASSERT_TRUE(back.outcome.validation);
  EXPECT_EQ(back.outcome.validation->summary(), result.outcome.validation->summary());
  EXPECT_EQ(back.outcome.ran, result.outcome.ran);
  EXPECT_EQ(back.outcome.returned, result.outcome.returned);
  EXPECT_EQ(back.outcome.element, result.outcome.element);
  EXPECT_EQ(back.outcome.output, result.outcome.output);
  ASSERT_EQ(result.outcome.output.size(), 1u);
  EXPECT_EQ(result.outcome.output[0], "flipped\tinf");
  ASSERT_EQ(back.outcome.edits.size(), result.outcome.edits.size());
  for (size_t i = 0; i < result.outcome.edits.size(); ++i) {
    EXPECT_EQ(describe(back.outcome.edits[i]), describe(result.outcome.edits[i])) << i;
    EXPECT_EQ(back.outcome.edits[i].where, result.outcome.edits[i].where) << i;
    EXPECT_EQ(back.outcome.edits[i].before.element, result.outcome.edits[i].before.element) << i;
  }
  ASSERT_EQ(back.outcome.touched.has_value(), result.outcome.touched.has_value());
  if (result.outcome.touched) {
    EXPECT_EQ(back.outcome.touched->written, result.outcome.touched->written);
  }
  // The replay of the edits that came back ends where the student's mesh did.
  EXPECT_TRUE(replay(*cube(), back.outcome.edits, back.outcome.edits.size()).same_as(*result.outcome.mesh));
}

TEST(StudentCallText, AnUpsampleKeepsItsRecordedStates) {
  StudentCall call;
  call.exercise = Exercise::Upsample;
  call.input = ExerciseInput::whole_mesh(cube());
  call.files = {solution("flip.lua"), solution("split.lua"), solution("upsample.lua")};
  const StudentCallResult result = run_student_call(call);
  ASSERT_TRUE(result.outcome.ran) << result.load_error << result.outcome.error;
  const StudentCallResult back = round_trip(result);
  ASSERT_EQ(back.outcome.edits.size(), result.outcome.edits.size());
  size_t states = 0;
  for (size_t i = 0; i < result.outcome.edits.size(); ++i) {
    ASSERT_EQ(back.outcome.edits[i].state != nullptr, result.outcome.edits[i].state != nullptr) << i;
    if (!result.outcome.edits[i].state) continue;
    ++states;
    EXPECT_TRUE(back.outcome.edits[i].state->same_as(*result.outcome.edits[i].state)) << i;
  }
  EXPECT_TRUE(back.outcome.mesh->same_as(*result.outcome.mesh));
  EXPECT_TRUE(replay(*cube(), back.outcome.edits, back.outcome.edits.size()).same_as(*result.outcome.mesh))
      << states << " recorded states";
}

TEST(StudentCallText, ErrorsAndLimitsComeBack) {
  StudentCallResult result;
  result.load_error = "flip.lua:3: unexpected symbol";
  result.thrown = "a bug";
  result.out_of_memory = true;
  result.outcome.limit = ScriptError::Limit::Time;
  result.outcome.error = "flip.lua:4: time limit exceeded (5 s)";
  const StudentCallResult back = round_trip(result);
  EXPECT_EQ(back.load_error, result.load_error);
  EXPECT_EQ(back.thrown, result.thrown);
  EXPECT_TRUE(back.out_of_memory);
  EXPECT_EQ(back.outcome.limit, ScriptError::Limit::Time);
  EXPECT_EQ(back.outcome.error, result.outcome.error);
  EXPECT_FALSE(back.outcome.mesh);
  EXPECT_FALSE(back.outcome.validation);
}

TEST(StudentCallText, BytesThatAreNotACallAreRefusedWithWhy) {
  const std::vector<uint8_t> junk = {0x01, 0x02, 0xff};
  try {
    decode_student_call(junk);
    FAIL() << "junk decoded";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("not a student call: ", 0), 0u) << e.what();
  }
  // A result is not a call.
  EXPECT_THROW(decode_student_call(encode_student_call_result(StudentCallResult{})), std::runtime_error);
  // The exercise goes by name: a name this process does not know is named.
  std::vector<uint8_t> bytes = encode_student_call(flip_call({}));
  const std::string flip = "flip";
  for (size_t i = 0; i + flip.size() <= bytes.size(); ++i) {
    if (std::string(bytes.begin() + i, bytes.begin() + i + flip.size()) == flip &&
        std::string(bytes.begin() + i, bytes.begin() + i + 5) != "flip_") {
      bytes[i] = 'g';  // "glip"
      break;
    }
  }
  try {
    decode_student_call(bytes);
    FAIL() << "an unknown exercise decoded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("glip"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshedit
