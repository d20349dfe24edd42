// ShaderLibrary: where shaders are found, and errors that name the paths tried, the file and the
// driver's log. Compiling needs an EGL context; finding files does not.
#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "render/render_error.h"
#include "render/shader_library.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const RenderError& e) {
    return e.what();
  }
  return "";
}

TEST(ShaderLibrary, DefaultSearchEndsInTheSourceTreeAndFindsEveryShader) {
  const ShaderLibrary library;
  ASSERT_FALSE(library.search_dirs().empty());
  EXPECT_EQ(library.search_dirs().back(), testing::source_dir() / "shaders");
  for (const char* name : {"face.vert", "face.frag", "face_pick.frag", "segment.vert", "segment.frag", "id.frag",
                           "point.vert", "point.frag"}) {
    EXPECT_TRUE(fs::is_regular_file(library.find(name))) << name;
    // One source for GLSL 330 and GLSL ES 3.00: the loader supplies the #version line (render/gl_api.h).
    EXPECT_EQ(library.read(name).find("#version"), std::string::npos) << name;
    EXPECT_NE(library.read(name).find("void main()"), std::string::npos) << name;
  }
}

TEST(ShaderLibrary, TheEnvironmentVariableComesFirst) {
  const fs::path dir = testing::scratch_dir();
  std::ofstream(dir / "face.vert") << "// mine\nvoid main() {}\n";
  ::setenv("MESHEDIT_SHADERS", dir.c_str(), 1);
  const ShaderLibrary library;
  ::unsetenv("MESHEDIT_SHADERS");
  EXPECT_EQ(library.search_dirs().front(), dir);
  EXPECT_EQ(library.find("face.vert"), dir / "face.vert");
  // A file that directory lacks comes from the next place that has it.
  EXPECT_EQ(library.find("face.frag"), testing::source_dir() / "shaders" / "face.frag");
}

TEST(ShaderLibrary, AMissingShaderNamesEveryPathTried) {
  const fs::path a = testing::scratch_dir() / "a", b = testing::scratch_dir() / "b";
  const ShaderLibrary library({a, b});
  const std::string message = error_of([&] { library.find("nowhere.frag"); });
  EXPECT_NE(message.find("nowhere.frag not found"), std::string::npos) << message;
  EXPECT_NE(message.find((a / "nowhere.frag").string()), std::string::npos) << message;
  EXPECT_NE(message.find((b / "nowhere.frag").string()), std::string::npos) << message;
  EXPECT_NE(message.find("MESHEDIT_SHADERS"), std::string::npos) << message;
  const ShaderLibrary empty(std::vector<fs::path>{});
  EXPECT_NE(error_of([&] { empty.find("x.vert"); }).find("no directories"), std::string::npos);
}

class ShaderCompile : public testing::GlTest {};

TEST_F(ShaderCompile, EveryProgramTheRenderersUseBuilds) {
  const ShaderLibrary library;
  for (const auto& [vert, frag] : {std::pair{"face.vert", "face.frag"},
                                   {"face.vert", "face_pick.frag"},
                                   {"segment.vert", "segment.frag"},
                                   {"segment.vert", "id.frag"},
                                   {"point.vert", "point.frag"},
                                   {"point.vert", "id.frag"}}) {
    const ShaderProgram program = library.program(vert, frag);
    EXPECT_NE(program.id(), 0u);
    EXPECT_EQ(program.name(), std::string(vert) + " + " + frag);
  }
}

TEST_F(ShaderCompile, ACompileErrorQuotesTheFileAndTheDriversLog) {
  const fs::path dir = testing::scratch_dir();
  std::ofstream(dir / "broken.frag") << "out vec4 c;\nvoid main() { c = undefined_thing; }\n";
  const ShaderLibrary library({dir, testing::source_dir() / "shaders"});
  const std::string message = error_of([&] { library.program("face.vert", "broken.frag"); });
  EXPECT_NE(message.find((dir / "broken.frag").string() + " does not compile"), std::string::npos) << message;
  EXPECT_NE(message.find("undefined_thing"), std::string::npos) << message;  // from the driver's log
  // The log counts lines as the file does (the loader's prologue ends in #line 1): undefined_thing is on line 2.
  EXPECT_NE(message.find("0:2("), std::string::npos) << message;
}

TEST_F(ShaderCompile, ALinkErrorNamesBothFiles) {
  const fs::path dir = testing::scratch_dir();
  // Compiles alone, but declares a uniform point.vert also has, with another type.
  std::ofstream(dir / "lonely.frag") << "uniform vec3 u_view;\nout vec4 c;\n"
                                        "void main() { c = vec4(u_view, 1.0); }\n";
  const ShaderLibrary library({dir, testing::source_dir() / "shaders"});
  const std::string message = error_of([&] { library.program("point.vert", "lonely.frag"); });
  EXPECT_NE(message.find("do not link"), std::string::npos) << message;
  EXPECT_NE(message.find("point.vert"), std::string::npos) << message;
  EXPECT_NE(message.find("lonely.frag"), std::string::npos) << message;
}

}  // namespace
}  // namespace meshedit
