// A file's up axis: the format table for every extension, the COLLADA rule (the tag, its default, the course's
// mistagged exporter), what load_file carries, and the course files themselves (skipped when absent).
#include "io/file_up_axis.h"

#include <gtest/gtest.h>

#include <map>

#include "core/primitives.h"
#include "io/file_access.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

constexpr std::string_view kCourseExporter = "modo 801 [Build 77509], Mac OS X 10.9.3 (10.9.3)";

TEST(FileUpAxis, EachFormatHasItsUpAxisInAnyCase) {
  EXPECT_EQ(format_up_axis("spot.obj"), UpAxis::Y);
  EXPECT_EQ(format_up_axis("Spot.OBJ"), UpAxis::Y);
  EXPECT_EQ(format_up_axis("a/b.gltf"), UpAxis::Y);
  EXPECT_EQ(format_up_axis("b.GLB"), UpAxis::Y);
  EXPECT_EQ(format_up_axis("bunny.ply"), UpAxis::Y);
  EXPECT_EQ(format_up_axis("part.Stl"), UpAxis::Z);
  EXPECT_EQ(format_up_axis("chair.OFF"), UpAxis::Z);
  EXPECT_EQ(format_up_axis("cow.dae"), UpAxis::Y);  // COLLADA's default, for a file without <up_axis>
  EXPECT_EQ(format_up_axis("teapot.bez"), UpAxis::Z);
  EXPECT_EQ(format_up_axis("curve1.bzc"), std::nullopt);
  EXPECT_EQ(format_up_axis("notes.txt"), std::nullopt);
  EXPECT_EQ(format_up_axis("README"), std::nullopt);
}

TEST(FileUpAxis, ColladaTrustsItsTag) {
  DaeAsset asset;
  asset.authoring_tool = "Blender 2.72.0 commit date:2014-10-21, commit time:11:38, hash:9e963ae";
  asset.up_axis_tagged = true;
  for (UpAxis axis : {UpAxis::X, UpAxis::Y, UpAxis::Z}) {
    asset.up_axis = axis;
    const FileUpAxis got = collada_up_axis(asset);
    EXPECT_EQ(got.up_axis, axis);
    EXPECT_EQ(got.source, UpAxisSource::FileTag);
  }
}

TEST(FileUpAxis, ColladaWithoutATagIsYUpByTheFormat) {
  const FileUpAxis got = collada_up_axis(DaeAsset{});
  EXPECT_EQ(got.up_axis, UpAxis::Y);
  EXPECT_EQ(got.source, UpAxisSource::Format);
}

TEST(FileUpAxis, TheCourseExporterIsZUpWhateverItsTagSays) {
  DaeAsset asset;
  asset.authoring_tool = std::string(kCourseExporter);
  asset.up_axis_tagged = true;
  asset.up_axis = UpAxis::Y;
  FileUpAxis got = collada_up_axis(asset);
  EXPECT_EQ(got.up_axis, UpAxis::Z);
  EXPECT_EQ(got.source, UpAxisSource::CourseExporter);
  asset.up_axis_tagged = false;
  EXPECT_EQ(collada_up_axis(asset).up_axis, UpAxis::Z);
  // Only that exact exporter: other modo builds and systems keep their tag.
  for (const char* other : {"modo 801 [Build 77509], Mac OS X 10.10 (10.10)", "modo 901 [Build 89716], Windows",
                            "modo 801 [Build 77509]"}) {
    asset.authoring_tool = other;
    asset.up_axis_tagged = true;
    got = collada_up_axis(asset);
    EXPECT_EQ(got.up_axis, UpAxis::Y) << other;
    EXPECT_EQ(got.source, UpAxisSource::FileTag) << other;
  }
}

TEST(FileUpAxis, LoadFileCarriesTheUpAxis) {
  const auto dir = testing::scratch_dir();
  save_mesh(dir / "cube.obj", make_cube());
  save_mesh(dir / "cube.glb", make_cube());
  save_mesh(dir / "cube.ply", make_cube());
  save_mesh(dir / "cube.stl", make_cube());
  write_file(dir / "tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  write_file(dir / "c.bzc", "2\n0 0 1 1\n");
  const std::string collada =
      "<COLLADA version=\"1.4.1\">\n<asset><up_axis>X_UP</up_axis></asset>\n<library_geometries>\n"
      "<geometry id=\"T\"><mesh><source id=\"T-pos\"><float_array id=\"a\" count=\"9\">0 0 0 1 0 0 0 1 0</float_array>"
      "</source><vertices id=\"T-vtx\"><input semantic=\"POSITION\" source=\"#T-pos\"/></vertices>"
      "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#T-vtx\" offset=\"0\"/><p>0 1 2</p></triangles>"
      "</mesh></geometry>\n</library_geometries>\n</COLLADA>\n";
  write_file(dir / "x.dae", collada);
  EXPECT_EQ(load_file(dir / "cube.obj").up_axis.up_axis, UpAxis::Y);
  EXPECT_EQ(load_file(dir / "cube.glb").up_axis.up_axis, UpAxis::Y);
  EXPECT_EQ(load_file(dir / "cube.ply").up_axis.up_axis, UpAxis::Y);
  EXPECT_EQ(load_file(dir / "cube.stl").up_axis.up_axis, UpAxis::Z);
  EXPECT_EQ(load_file(dir / "tri.off").up_axis.up_axis, UpAxis::Z);
  EXPECT_EQ(load_file(dir / "c.bzc").up_axis.up_axis, UpAxis::Z);
  const FileUpAxis dae = load_file(dir / "x.dae").up_axis;
  EXPECT_EQ(dae.up_axis, UpAxis::X);
  EXPECT_EQ(dae.source, UpAxisSource::FileTag);
}

TEST(FileUpAxis, EveryCourseFileIsZUp) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  // The modo files are tagged Y_UP but Z-up (file_up_axis.h); the Blender ones are tagged Z_UP.
  const std::map<std::string, UpAxisSource> dae = {{"bean.dae", UpAxisSource::CourseExporter},
                                                   {"beetle.dae", UpAxisSource::CourseExporter},
                                                   {"cow.dae", UpAxisSource::CourseExporter},
                                                   {"peter.dae", UpAxisSource::CourseExporter},
                                                   {"quadball.dae", UpAxisSource::CourseExporter},
                                                   {"teapot.dae", UpAxisSource::CourseExporter},
                                                   {"cube.dae", UpAxisSource::FileTag},
                                                   {"weird.dae", UpAxisSource::FileTag}};
  for (const auto& [name, source] : dae) {
    SCOPED_TRACE(name);
    const DaeFile file = read_dae_file(dir / "dae" / name);
    EXPECT_TRUE(file.asset.up_axis_tagged);
    EXPECT_EQ(file.asset.up_axis, source == UpAxisSource::FileTag ? UpAxis::Z : UpAxis::Y);
    const FileUpAxis got = load_file(dir / "dae" / name).up_axis;
    EXPECT_EQ(got.up_axis, UpAxis::Z);
    EXPECT_EQ(got.source, source);
  }
  for (const char* name : {"teapot.bez", "wavy_cube.bez"}) {
    EXPECT_EQ(load_file(dir / "bez" / name).up_axis.up_axis, UpAxis::Z) << name;
  }
}

}  // namespace
}  // namespace meshedit
