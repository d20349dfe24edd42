// Dispatch by extension: every kind, case-insensitive extensions, unknown extensions, missing and
// unreadable files, and saving.
#include "io/mesh_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "core/primitives.h"
#include "io/file_access.h"
#include "io_test_util.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

TEST(MeshFile, KindsFollowTheExtensionInAnyCase) {
  EXPECT_EQ(file_kind("a.obj"), FileKind::Mesh);
  EXPECT_EQ(file_kind("dir.x/A.DAE"), FileKind::Mesh);
  EXPECT_EQ(file_kind("a.GlTf"), FileKind::Mesh);
  EXPECT_EQ(file_kind("a.glb"), FileKind::Mesh);
  EXPECT_EQ(file_kind("teapot.Bez"), FileKind::Patches);
  EXPECT_EQ(file_kind("curve1.BZC"), FileKind::Curve);
  EXPECT_FILE_ERROR(file_kind("model.stl"), "model.stl: unsupported file type '.stl'", ".obj", ".dae", ".gltf", ".glb",
                    ".bez", ".bzc");
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
  for (const char* name : {"m.OBJ", "m.gltf", "m.glb"}) {
    const LoadedFile loaded = load_file(dir / name);
    EXPECT_EQ(loaded.kind, FileKind::Mesh);
    testing::expect_same_mesh(loaded.mesh, make_cube());  // the cube's coordinates are exact floats
    testing::expect_same_mesh(load_mesh(dir / name), make_cube());
  }
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
                    ".obj, .gltf or .glb");
  EXPECT_FILE_ERROR(save_mesh(dir / "no_such_dir" / "m.obj", make_cube()),
                    "m.obj: cannot write: No such file or directory");
  EXPECT_FALSE(std::filesystem::exists(dir / "m.dae"));
}

}  // namespace
}  // namespace meshedit
