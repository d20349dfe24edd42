// Dispatch by extension: the lists of formats, every kind, case-insensitive extensions, unknown extensions, missing
// and unreadable files, and saving; the docs and the web page's file picker list the table's formats.
#include "io/mesh_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "core/primitives.h"
#include "io/file_access.h"
#include "io_test_util.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(MeshFile, TheListsOfFormatsComeFromTheTable) {
  using V = std::vector<std::string>;
  EXPECT_EQ(readable_extensions(FileKind::Mesh), (V{".obj", ".dae", ".gltf", ".glb", ".ply", ".stl", ".off"}));
  EXPECT_EQ(readable_extensions(FileKind::Patches), V{".bez"});
  EXPECT_EQ(readable_extensions(FileKind::Curve), V{".bzc"});
  EXPECT_EQ(writable_extensions(), (V{".obj", ".gltf", ".glb", ".ply", ".stl"}));
  for (FileKind kind : {FileKind::Mesh, FileKind::Patches, FileKind::Curve}) {
    for (const std::string& ext : readable_extensions(kind)) EXPECT_EQ(file_kind("a" + ext), kind) << ext;
  }
  EXPECT_EQ(list_extensions(writable_extensions(), ", ", " or "), ".obj, .gltf, .glb, .ply or .stl");
  EXPECT_EQ(list_extensions({".bez"}, ", ", " or "), ".bez");
  EXPECT_EQ(list_extensions({}, ", ", " or "), "");
}

// Each page that lists the formats lists the table's, in its order, so a new reader cannot be left out of them.
TEST(MeshFile, TheDocsAndTheWebPageListTheTablesFormats) {
  const auto text = [](const char* file) { return testing::words_of(file); };
  const std::vector<std::string> meshes = readable_extensions(FileKind::Mesh),
                                 patches = readable_extensions(FileKind::Patches),
                                 curves = readable_extensions(FileKind::Curve), written = writable_extensions();
  const std::string read_meshes = list_extensions(meshes, " ", " "), write = list_extensions(written, " ", " ");
  const std::string converted = list_extensions(joined(meshes, patches), " ", " ");
  EXPECT_NE(text("README.md").find("`" + converted + "` to `" + write + "`"), std::string::npos);
  EXPECT_NE(text("docs/COMMANDS.md").find(converted + " -> " + write), std::string::npos);
  EXPECT_NE(text("docs/COMMANDS.md").find("`" + read_meshes + "` and written to `" + write + "`"), std::string::npos);
  EXPECT_NE(text("docs/WINDOW.md").find("a mesh (`" + read_meshes + "`)"), std::string::npos);
  EXPECT_NE(text("docs/ARCHITECTURE.md")
                .find("readers of `" + list_extensions(joined(joined(meshes, patches), curves), " ", " ") +
                      "`, writers of `" + write + "`"),
            std::string::npos);
  // The page's file picker: every file the app reads, glTF's .bin buffers and lessons.
  const std::string accept =
      list_extensions(joined(joined(joined(meshes, {".bin"}), patches), joined(curves, {".lua"})), ",", ",");
  EXPECT_NE(text("web/index.html").find("accept=\"" + accept + "\""), std::string::npos) << accept;
}

TEST(MeshFile, KindsFollowTheExtensionInAnyCase) {
  EXPECT_EQ(file_kind("a.obj"), FileKind::Mesh);
  EXPECT_EQ(file_kind("dir.x/A.DAE"), FileKind::Mesh);
  EXPECT_EQ(file_kind("a.GlTf"), FileKind::Mesh);
  EXPECT_EQ(file_kind("a.glb"), FileKind::Mesh);
  EXPECT_EQ(file_kind("teapot.Bez"), FileKind::Patches);
  EXPECT_EQ(file_kind("curve1.BZC"), FileKind::Curve);
  EXPECT_EQ(file_kind("bunny.PLY"), FileKind::Mesh);
  EXPECT_EQ(file_kind("part.stl"), FileKind::Mesh);
  EXPECT_EQ(file_kind("chair.Off"), FileKind::Mesh);
  EXPECT_FILE_ERROR(file_kind("model.3ds"), "model.3ds: unsupported file type '.3ds'", ".obj", ".dae", ".gltf", ".glb",
                    ".ply", ".stl", ".off", ".bez", ".bzc");
  EXPECT_TRUE(is_readable("a/B.STL"));
  EXPECT_TRUE(is_readable("c.bzc"));
  EXPECT_FALSE(is_readable("model.3ds"));
  EXPECT_FALSE(is_readable("README"));
  EXPECT_FILE_ERROR(file_kind("README"), "README: file has no extension");
}

TEST(MeshFile, LoadsEveryKind) {
  const auto dir = testing::scratch_dir();
  write_file(dir / "c.BZC", "2\n0 0 1 1\n");
  write_file(dir / "p.bez", "1\n" + std::string(48 * 2, ' ').replace(0, 1, "0") + "\n");
  const LoadedFile curve = load_file(dir / "c.BZC");
  EXPECT_EQ(curve.kind, FileKind::Curve);
  ASSERT_EQ(curve.curve.control_points.size(), 2u);
  EXPECT_EQ(curve.curve.control_points[1], glm::dvec2(1, 1));
  // 48 numbers are needed; the file holds one.
  EXPECT_FILE_ERROR(load_file(dir / "p.bez"), "p.bez:", "declares 1 patches but holds only 1 numbers");

  save_mesh(dir / "m.OBJ", make_cube());
  save_mesh(dir / "m.gltf", make_cube());
  save_mesh(dir / "m.glb", make_cube());
  save_mesh(dir / "m.ply", make_cube());
  save_mesh(dir / "m.Stl", make_cube());
  for (const char* name : {"m.OBJ", "m.gltf", "m.glb", "m.ply"}) {
    const LoadedFile loaded = load_file(dir / name);
    EXPECT_EQ(loaded.kind, FileKind::Mesh);
    testing::expect_same_mesh(loaded.mesh, make_cube());  // the cube's coordinates are exact floats
    testing::expect_same_mesh(load_mesh(dir / name), make_cube());
  }
  // STL stores each triangle's corners; read back, they are welded into the cube's 8 vertices again.
  const PolygonMesh stl = load_mesh(dir / "m.Stl");
  EXPECT_EQ(stl.num_vertices(), 8u);
  testing::expect_same_face_positions(stl, make_cube());
  write_file(dir / "t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(load_mesh(dir / "t.off").indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_FILE_ERROR(load_mesh(dir / "c.BZC"), "c.BZC: holds a Bézier curve, not a mesh");
}

TEST(MeshFile, MissingAndUnreadableFilesNameTheReason) {
  const auto dir = testing::scratch_dir();
  EXPECT_FILE_ERROR(load_file(dir / "absent.obj"), "absent.obj: cannot open: No such file or directory");
  std::filesystem::create_directory(dir / "folder.obj");
  EXPECT_FILE_ERROR(load_file(dir / "folder.obj"), "folder.obj: cannot open: Is a directory");
  EXPECT_FILE_ERROR(load_file(dir / "nothing.dae"), "nothing.dae: cannot open: No such file or directory");
  write_file(dir / "empty.obj", "");
  EXPECT_FILE_ERROR(load_file(dir / "empty.obj"), "empty.obj:1: file is empty");
  write_file(dir / "empty.glb", "");
  EXPECT_FILE_ERROR(load_file(dir / "empty.glb"), "empty.glb: file is empty");
  EXPECT_FILE_ERROR(load_file("/dev/null.bez"), "/dev/null.bez: cannot open");
  // Devices and FIFOs are refused before reading: /dev/zero never ends, a FIFO may never deliver.
  EXPECT_FILE_ERROR(read_file("/dev/zero"), "/dev/zero: cannot open: not a regular file");
  ASSERT_EQ(mkfifo((dir / "pipe.obj").c_str(), 0600), 0);
  EXPECT_FILE_ERROR(load_file(dir / "pipe.obj"), "pipe.obj: cannot open: not a regular file");
}

TEST(MeshFile, SavingRefusesOtherExtensionsAndUnwritablePlaces) {
  const auto dir = testing::scratch_dir();
  EXPECT_FILE_ERROR(save_mesh(dir / "m.dae", make_cube()), "m.dae: unsupported file type '.dae' for saving",
                    ".obj, .gltf, .glb, .ply or .stl");
  EXPECT_FILE_ERROR(save_mesh(dir / "no_such_dir" / "m.obj", make_cube()),
                    "m.obj: cannot write: No such file or directory");
  EXPECT_FALSE(std::filesystem::exists(dir / "m.dae"));
}

}  // namespace
}  // namespace meshedit
