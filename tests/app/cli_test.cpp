// The real `meshedit` binary on the shell: exit statuses, one-line errors, info/convert/subdivide on
// procedural meshes and on every course file.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/cli_test_support.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

using testing::CommandRun;

CommandRun meshedit(const std::vector<std::string>& args) { return testing::run_meshedit(args, "cli-run"); }

nlohmann::json info_json(const fs::path& file) {
  const CommandRun run = meshedit({"info", file.string(), "--json"});
  EXPECT_EQ(run.status, 0) << run.err;
  return nlohmann::json::parse(run.out);
}

size_t line_count(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

TEST(Cli, HelpAndUnknownCommand) {
  const CommandRun help = meshedit({"--help"});
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("subdivide IN -n LEVELS"), std::string::npos);
  // convert's formats are the table's (io/mesh_file.h): meshes and patches in, what save_mesh writes out.
  std::vector<std::string> in = readable_extensions(FileKind::Mesh);
  in.push_back(readable_extensions(FileKind::Patches).at(0));
  EXPECT_NE(help.out.find("(" + list_extensions(in, " ", " ") + " -> " +
                          list_extensions(writable_extensions(), " ", " ") + ")"),
            std::string::npos)
      << help.out;
  // A command's own --help: its lines of the same text.
  const CommandRun grade_help = meshedit({"grade", "--help"});
  EXPECT_EQ(grade_help.status, 0) << grade_help.err;
  EXPECT_EQ(grade_help.out.rfind("usage: meshedit grade --suite SUITE.lua --submission DIR", 0), 0u) << grade_help.out;
  EXPECT_NE(grade_help.out.find("--submissions DIR..."), std::string::npos) << grade_help.out;
  EXPECT_EQ(meshedit({"run", "-h"}).out.rfind("usage: meshedit run SCRIPT.lua [ARGS...]", 0), 0u);
  const CommandRun bad = meshedit({"frobnicate"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "meshedit: unknown command 'frobnicate' (see meshedit --help)\n");
}

TEST(Cli, InfoOnAClosedMesh) {
  const fs::path file = testing::scratch_dir() / "torus.obj";
  save_mesh(file, make_torus(8, 4));
  const nlohmann::json j = info_json(file);
  EXPECT_EQ(j["kind"], "mesh");
  EXPECT_EQ(j["vertices"], 32);
  EXPECT_EQ(j["edges"], 96);
  EXPECT_EQ(j["faces"], 64);
  EXPECT_EQ(j["halfedges"], 192);
  EXPECT_EQ(j["boundary_loops"], 0);
  EXPECT_EQ(j["euler_characteristic"], 0);
  EXPECT_EQ(j["genus"], 1);
  EXPECT_EQ(j["valid"], true);

  const CommandRun text = meshedit({"info", file.string()});
  EXPECT_EQ(text.status, 0);
  EXPECT_NE(text.out.find("Euler characteristic  0 (closed)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("validation            valid"), std::string::npos) << text.out;
}

TEST(Cli, ErrorsAreOneLineAndNonZero) {
  const fs::path dir = testing::scratch_dir();
  const fs::path broken = dir / "broken.obj";
  std::ofstream(broken) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n";
  const fs::path non_manifold = dir / "three_faces.obj";
  std::ofstream(non_manifold) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\n"
                              << "f 1 2 3\nf 2 1 4\nf 1 2 5\n";
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"info", (dir / "missing.obj").string()},
           {"info", broken.string()},
           {"info", non_manifold.string()},
           {"info", (dir / "x.xyz").string()},
           {"subdivide", broken.string(), "-n", "1", "-o", (dir / "o.obj").string()},
           {"subdivide", non_manifold.string(), "-n", "two", "-o", (dir / "o.obj").string()},
           {"convert", broken.string()},
       }) {
    const CommandRun run = meshedit(args);
    EXPECT_NE(run.status, 0) << args[0] << " " << args[1];
    EXPECT_EQ(line_count(run.err), 1u) << run.err;
    EXPECT_EQ(run.err.rfind("meshedit: ", 0), 0u) << run.err;
  }
  const CommandRun three = meshedit({"info", non_manifold.string()});
  EXPECT_NE(three.err.find("three_faces.obj"), std::string::npos) << three.err;
  EXPECT_NE(three.err.find("shared by 3 faces"), std::string::npos) << three.err;
  // A face the readers keep for repair (two corners) is named by the file it is in, with the way out.
  const fs::path short_face = dir / "short_face.obj";
  std::ofstream(short_face) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n";
  const CommandRun convert = meshedit({"convert", short_face.string(), (dir / "out.ply").string()});
  EXPECT_EQ(convert.status, 1);
  EXPECT_EQ(convert.err, "meshedit: " + short_face.string() + ": face 1: has 2 corners; at least 3 are needed; " +
                             "meshedit repair " + short_face.string() + " -o OUT drops it, with a report\n");
  EXPECT_FALSE(fs::exists(dir / "out.ply"));
}

TEST(Cli, SubdivideWritesTheRefinedMesh) {
  const fs::path dir = testing::scratch_dir();
  save_mesh(dir / "cube.obj", make_cube());
  const CommandRun run = meshedit(
      {"subdivide", (dir / "cube.obj").string(), "-n", "2", "--weights", "loop", "-o", (dir / "cube2.obj").string()});
  ASSERT_EQ(run.status, 0) << run.err;
  const nlohmann::json j = info_json(dir / "cube2.obj");
  // V' = V + E, F' = 4F per level: 8 -> 26 -> 98 vertices, 12 -> 48 -> 192 faces.
  EXPECT_EQ(j["vertices"], 98);
  EXPECT_EQ(j["faces"], 192);
  EXPECT_EQ(j["valid"], true);
  EXPECT_EQ(j["genus"], 0);
}

TEST(Cli, ConvertRoundTripsBetweenFormats) {
  const fs::path dir = testing::scratch_dir();
  save_mesh(dir / "ico.obj", make_icosahedron());
  for (const char* ext : {".gltf", ".glb", ".obj", ".ply", ".stl"}) {
    const fs::path out = dir / (std::string("ico_out") + ext);
    const CommandRun run = meshedit({"convert", (dir / "ico.obj").string(), out.string()});
    ASSERT_EQ(run.status, 0) << run.err;
    const nlohmann::json j = info_json(out);
    EXPECT_EQ(j["vertices"], 12) << ext;
    EXPECT_EQ(j["faces"], 20) << ext;
    EXPECT_EQ(j["valid"], true) << ext;
  }
}

TEST(Cli, InfoAndConvertReadOffPlyAndStl) {
  const fs::path dir = testing::scratch_dir();
  // A tetrahedron as ModelNet writes OFF: the counts glued to the keyword.
  std::ofstream(dir / "tet.off") << "OFF4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
  nlohmann::json j = info_json(dir / "tet.off");
  EXPECT_EQ(j["vertices"], 4);
  EXPECT_EQ(j["faces"], 4);
  EXPECT_EQ(j["genus"], 0);
  EXPECT_EQ(j["valid"], true);
  ASSERT_EQ(meshedit({"convert", (dir / "tet.off").string(), (dir / "tet.stl").string()}).status, 0);
  ASSERT_EQ(meshedit({"convert", (dir / "tet.stl").string(), (dir / "tet.ply").string()}).status, 0);
  j = info_json(dir / "tet.ply");
  EXPECT_EQ(j["vertices"], 4);  // the STL's twelve corners welded back into four vertices
  EXPECT_EQ(j["faces"], 4);
  EXPECT_EQ(j["valid"], true);

  std::ofstream(dir / "bad.ply") << "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n"
                                 << "property float y\nproperty float z\nelement face 1\n"
                                 << "property list uchar int vertex_indices\nend_header\n";
  const CommandRun bad = meshedit({"info", (dir / "bad.ply").string()});
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("bad.ply:3: declares 4000000000 vertices"), std::string::npos) << bad.err;
}

TEST(Cli, InfoAndSubdivideOnEveryCourseFile) {
  MESHEDIT_REQUIRE_COURSE_DATA(data);
  const fs::path dir = testing::scratch_dir();
  size_t files = 0;
  for (const char* folder : {"dae", "bez", "bzc"}) {
    for (const auto& entry : fs::directory_iterator(data / folder)) {
      const fs::path file = entry.path();
      SCOPED_TRACE(file.string());
      ++files;
      const nlohmann::json j = info_json(file);
      if (j["kind"] == "curve") {
        EXPECT_GE(j["points"].get<int>(), 4);
        continue;
      }
      const nlohmann::json m = j["kind"] == "patches" ? j["tessellation"] : j;
      ASSERT_TRUE(m.is_object()) << j.dump();
      EXPECT_EQ(m["valid"], true);
      const fs::path out = dir / (file.stem().string() + "_1.obj");
      const CommandRun run = meshedit({"subdivide", file.string(), "-n", "1", "-o", out.string()});
      ASSERT_EQ(run.status, 0) << run.err;
      const nlohmann::json s = info_json(out);
      EXPECT_EQ(s["vertices"], m["vertices"].get<int>() + m["edges"].get<int>());
      EXPECT_EQ(s["faces"], 4 * m["faces"].get<int>());
      EXPECT_EQ(s["boundary_loops"], m["boundary_loops"]);
      EXPECT_EQ(s["valid"], true);
    }
  }
  EXPECT_EQ(files, 12u);
  const nlohmann::json teapot = info_json(data / "dae" / "teapot.dae");
  EXPECT_EQ(teapot["vertices"], 1232);
  EXPECT_EQ(teapot["faces"], 2464);
  EXPECT_EQ(info_json(data / "bez" / "teapot.bez")["patches"], 32);
  EXPECT_GT(info_json(data / "dae" / "beetle.dae")["boundary_loops"].get<int>(), 0);
}

TEST(Cli, DemoRunsOnTheProjectTeapot) {
  const CommandRun run = meshedit({"demo"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("32 Bézier patches"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("validate: valid"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("undo: the mesh is identical"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Loop subdivision in"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace meshedit
