// COLLADA: exact positions and faces of small hand-written files (primitives, sources, accessors,
// transforms, instancing), what <asset> says (up axis, authoring tool), and every refusal with its XML line and
// element.
#include "io/dae_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io_test_util.h"

namespace meshedit {
namespace {

// A document with the given geometries (inside <library_geometries>) and visual-scene nodes.
std::string document(const std::string& geometries, const std::string& nodes = "") {
  std::string text =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
      "<library_geometries>\n" +
      geometries + "</library_geometries>\n";
  if (!nodes.empty()) {
    text += "<library_visual_scenes>\n<visual_scene id=\"Scene\">\n" + nodes +
            "</visual_scene>\n</library_visual_scenes>\n<scene><instance_visual_scene url=\"#Scene\"/></scene>\n";
  }
  return text + "</COLLADA>\n";
}

// A geometry `id` whose positions are `floats` (x y z ...) and whose mesh body follows <vertices>.
std::string geometry(const std::string& id, const std::string& floats, const std::string& primitives,
                     const std::string& array_count = "") {
  size_t numbers = 0;
  for (size_t i = 0; i < floats.size(); ++i) {
    if (floats[i] != ' ' && (i == 0 || floats[i - 1] == ' ')) ++numbers;
  }
  const std::string count = array_count.empty() ? std::to_string(numbers) : array_count;
  return "<geometry id=\"" + id + "\">\n<mesh>\n<source id=\"" + id + "-pos\">\n<float_array id=\"" + id +
         "-arr\" count=\"" + count + "\">" + floats + "</float_array>\n</source>\n<vertices id=\"" + id +
         "-vtx\">\n<input semantic=\"POSITION\" source=\"#" + id + "-pos\"/>\n</vertices>\n" + primitives +
         "</mesh>\n</geometry>\n";
}

const std::string kSquare = "0 0 0  1 0 0  1 1 0  0 1 0";

std::string triangles(const std::string& id, const std::string& p, const std::string& count) {
  return "<triangles count=\"" + count + "\">\n<input semantic=\"VERTEX\" source=\"#" + id +
         "-vtx\" offset=\"0\"/>\n<input semantic=\"NORMAL\" source=\"#n\" offset=\"1\"/>\n<p>" + p +
         "</p>\n</triangles>\n";
}

std::string polylist(const std::string& id, const std::string& vcount, const std::string& p, const std::string& count) {
  return "<polylist count=\"" + count + "\">\n<input semantic=\"VERTEX\" source=\"#" + id +
         "-vtx\" offset=\"0\"/>\n<input semantic=\"NORMAL\" source=\"#n\" offset=\"1\"/>\n<vcount>" + vcount +
         "</vcount>\n<p>" + p + "</p>\n</polylist>\n";
}

TEST(Dae, ReadsTrianglesAndPolylistsUntransformedWithoutAScene) {
  // Geometry A: two triangles (normals interleaved at offset 1); geometry B: a quad and a triangle.
  const std::string a = geometry("A", kSquare, triangles("A", "0 9 1 9 2 9  0 9 2 9 3 9", "2"));
  const std::string b =
      geometry("B", kSquare + "  0.5 0.5 -2", polylist("B", "4 3", "0 0 1 0 2 0 3 0  0 0 4 0 1 0", "2"));
  const PolygonMesh m = parse_dae(document(a + b), "two.dae");
  ASSERT_EQ(m.num_vertices(), 9u);
  EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0));
  EXPECT_EQ(m.positions[8], glm::dvec3(0.5, 0.5, -2));
  ASSERT_EQ(m.num_faces(), 4u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 7, 4, 8, 5}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 3, 6, 10, 13}));
}

TEST(Dae, ReadsPolygonsFansStripsAndAccessorStrides) {
  // Positions stored with stride 4 and offset 1 (a padding number first, then x y z w).
  const std::string floats = "99  0 0 0 7  1 0 0 7  1 1 0 7  0 1 0 7  2 2 2 7";
  const std::string source =
      "<geometry id=\"G\"><mesh>\n<source id=\"G-pos\"><float_array count=\"21\">" + floats +
      "</float_array>\n<technique_common><accessor source=\"#x\" count=\"5\" stride=\"4\" offset=\"1\"/>"
      "</technique_common></source>\n<vertices id=\"G-vtx\"><input semantic=\"POSITION\" "
      "source=\"#G-pos\"/></vertices>\n"
      "<polygons count=\"1\"><input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/><p>0 1 2 3</p></polygons>\n"
      "<trifans count=\"1\"><input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/><p>4 0 1 2</p></trifans>\n"
      "<tristrips count=\"1\"><input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/><p>0 1 2 2 3 "
      "4</p></tristrips>\n"
      "<lines count=\"1\"><input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/><p>0 1</p></lines>\n"
      "</mesh></geometry>\n";
  const PolygonMesh m = parse_dae(document(source), "g.dae");
  ASSERT_EQ(m.num_vertices(), 5u);
  EXPECT_EQ(m.positions[0], glm::dvec3(0, 0, 0));
  EXPECT_EQ(m.positions[4], glm::dvec3(2, 2, 2));
  // polygon; fan (4 0 1) (4 1 2); strip (0 1 2), (2 1 2) and (2 2 3) degenerate and dropped, then
  // (3 2 4): the fourth triangle of a strip is odd, so its first two corners swap.
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 0, 1, 4, 1, 2, 0, 1, 2, 3, 2, 4}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 4, 7, 10, 13, 16}));
}

// A polygon of fewer than 3 corners, in a <polylist> or a <polygons>, is read as the file has it, for the builder to
// refuse by its number and mesh repair to drop with a report; a strip of fewer than 3 corners holds no triangle.
TEST(Dae, KeepsPolygonsOfFewerThanThreeCornersForRepair) {
  const PolygonMesh m =
      parse_dae(document(geometry("A", kSquare, polylist("A", "3 2 0", "0 0 1 0 2 0 3 0 0 0", "3"))), "cow.dae");
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 0}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 3, 5, 5}));
  const std::string polygons =
      "<polygons count=\"2\"><input semantic=\"VERTEX\" source=\"#A-vtx\" offset=\"0\"/><p>0 1 2 3</p>"
      "<p>2</p></polygons>\n";
  EXPECT_EQ(parse_dae(document(geometry("A", kSquare, polygons)), "cow.dae").face_offsets,
            (std::vector<uint32_t>{0, 4, 5}));
  const std::string strip =
      "<tristrips count=\"1\"><input semantic=\"VERTEX\" source=\"#A-vtx\" offset=\"0\"/><p>0 1</p>"
      "</tristrips>\n";
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", kSquare, strip)), "cow.dae"),
                    "cow.dae:12: <p> of <tristrips> has 2 corners; at least 3 are needed");
}

TEST(Dae, AppliesNodeTransformsPerInstance) {
  const std::string tri = geometry("T", "1 0 0  0 1 0  0 0 1", triangles("T", "0 0 1 0 2 0", "1"));
  const std::string never = geometry("U", "5 5 5  6 5 5  5 6 5", triangles("U", "0 0 1 0 2 0", "1"));
  const std::string nodes =
      "<node id=\"scaled\"><matrix>2 0 0 10  0 2 0 0  0 0 2 0  0 0 0 1</matrix>\n"
      "  <instance_geometry url=\"#T\"/>\n"
      "  <node id=\"child\"><translate>0 0 1</translate><rotate>0 0 1 90</rotate><scale>1 1 3</scale>\n"
      "    <instance_geometry url=\"#T\"/></node>\n"
      "</node>\n"
      "<node id=\"mirror\"><scale>-1 1 1</scale><instance_geometry url=\"#T\"/></node>\n"
      "<node id=\"camera\"><lookat>0 0 5 0 0 0 0 1 0</lookat></node>\n";
  const PolygonMesh m = parse_dae(document(tri + never, nodes), "t.dae");
  ASSERT_EQ(m.num_vertices(), 12u);
  // Instance 1: x' = 2x + 10, y' = 2y, z' = 2z.
  EXPECT_EQ(m.positions[0], glm::dvec3(12, 0, 0));
  EXPECT_EQ(m.positions[1], glm::dvec3(10, 2, 0));
  EXPECT_EQ(m.positions[2], glm::dvec3(10, 0, 2));
  // Instance 2: parent (2x + 10) after translate z+1, rotate 90 about z, scale z by 3.
  //   (1,0,0) -> rotate -> (0,1,0) -> +z1 -> (0,1,1) -> parent -> (10,2,2)
  //   (0,0,1) -> scale -> (0,0,3) -> +z1 -> (0,0,4) -> parent -> (10,0,8)
  EXPECT_NEAR(m.positions[3].x, 10, 1e-12);
  EXPECT_NEAR(m.positions[3].y, 2, 1e-12);
  EXPECT_NEAR(m.positions[3].z, 2, 1e-12);
  EXPECT_NEAR(m.positions[4].x, 8, 1e-12);  // (0,1,0) -> (-1,0,0) -> (-1,0,1) -> (8,0,2)
  EXPECT_NEAR(m.positions[4].y, 0, 1e-12);
  EXPECT_NEAR(m.positions[4].z, 2, 1e-12);
  EXPECT_NEAR(m.positions[5].z, 8, 1e-12);
  // Instance 3 is mirrored: positions negated in x and the triangle reversed to stay outward.
  EXPECT_EQ(m.positions[6], glm::dvec3(-1, 0, 0));
  // The geometry never instanced comes untransformed.
  EXPECT_EQ(m.positions[9], glm::dvec3(5, 5, 5));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 8, 7, 6, 9, 10, 11}));
}

TEST(Dae, RefusesMalformedXml) {
  EXPECT_FILE_ERROR(parse_dae("", "e.dae"), "e.dae:1: file is empty");
  EXPECT_FILE_ERROR(parse_dae("<COLLADA>\n<library_geometries>\n</COLLADA>", "e.dae"), "e.dae:", "malformed XML");
  EXPECT_FILE_ERROR(parse_dae("\n<mesh/>", "e.dae"), "e.dae:2: root element is <mesh>, expected <COLLADA>");
  std::string deep = "<COLLADA>";
  for (int i = 0; i < 5000; ++i) deep += "<node>";
  EXPECT_FILE_ERROR(parse_dae(deep, "e.dae"), "e.dae:1:", "nested deeper than");
  EXPECT_FILE_ERROR(parse_dae(std::string("\x89PNG\r\n\x1a\n\0\0\0", 11), "e.dae"), "e.dae:");
  EXPECT_FILE_ERROR(parse_dae(document(""), "e.dae"), "e.dae: file holds no triangles or polygons");
  // Truncated in the middle of an element.
  const std::string whole = document(geometry("A", kSquare, triangles("A", "0 0 1 0 2 0", "1")));
  EXPECT_FILE_ERROR(parse_dae(whole.substr(0, whole.find("<p>") + 6), "e.dae"), "e.dae:", "malformed XML");
}

TEST(Dae, RefusesBadGeometryWithLineAndElement) {
  const std::string ok_tri = triangles("A", "0 0 1 0 2 0", "1");
  // Line numbers: the document header takes lines 1-3; geometry() puts <geometry> on 4, <mesh> on 5,
  // <source> 6, <float_array> 7, </source> 8, <vertices> 9, <input> 10, </vertices> 11, primitives from 12.
  EXPECT_FILE_ERROR(
      parse_dae(document(geometry("A", "0 0 0 1 0 0 0 1 0", triangles("A", "0 0 1 0 2", "1"))), "cow.dae"),
      "cow.dae:15: <p> of <triangles> has 5 indices, expected a multiple of 2");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", "0 0 0 1 0 0 0 1 0", triangles("A", "0 0 1 0", "1"))), "cow.dae"),
                    "cow.dae:15: <p> of <triangles> holds 2 corners, expected a multiple of 3");
  EXPECT_FILE_ERROR(
      parse_dae(document(geometry("A", "0 0 0 1 0 0 0 1 0", triangles("A", "0 0 1 0 2 0", "2"))), "cow.dae"),
      "cow.dae:12: <triangles count=\"2\"> but it holds 1 triangles");
  EXPECT_FILE_ERROR(
      parse_dae(document(geometry("A", "0 0 0 1 0 0 0 1 0", triangles("A", "0 0 1 0 3 0", "1"))), "cow.dae"),
      "cow.dae:15: <p> of <triangles> refers to vertex 3, but the positions hold only 3");
  EXPECT_FILE_ERROR(
      parse_dae(document(geometry("A", "0 0 0 1 0 0 0 1 0", triangles("A", "0 0 1 0 -2 0", "1"))), "cow.dae"),
      "cow.dae:15:", "\"-2\"");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", "0 0 0 1 0 0 0 1 0", ok_tri, "10")), "cow.dae"),
                    "cow.dae:7: <float_array> declares count=\"10\" but holds 9 numbers");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", "0 0 0 1 0 0 0 1", ok_tri)), "cow.dae"),
                    "cow.dae:7: <float_array> holds 8 numbers, not a multiple of 3");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", "0 0 0 1 nan 0 0 1 0", ok_tri)), "cow.dae"),
                    "cow.dae:7: a number in <float_array> must be a finite number, found \"nan\"");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", "0 0 0 1 0 0 0 1 0.5x", ok_tri)), "cow.dae"),
                    "cow.dae:7: expected a number in <float_array>, found \"0.5x\"");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", "0 0 0\n1 0 0\n0 1 inf", ok_tri)), "cow.dae"),
                    "cow.dae:9:", "\"inf\"");
  EXPECT_FILE_ERROR(
      parse_dae(document(geometry("A", kSquare, polylist("A", "3 3", "0 0 1 0 2 0 3 0 0", "2"))), "cow.dae"),
      "cow.dae:16: <p> of <polylist> has 9 indices, expected a multiple of 2");
  EXPECT_FILE_ERROR(
      parse_dae(document(geometry("A", kSquare, polylist("A", "3 3", "0 0 1 0 2 0 3 0", "2"))), "cow.dae"),
      "cow.dae:16: <p> of <polylist> holds 4 corners, but <vcount> adds up to 6");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", kSquare, polylist("A", "4", "0 0 1 0 2 0 3 0", "3"))), "cow.dae"),
                    "cow.dae:12: <polylist count=\"3\"> but it holds 1 polygons");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", kSquare,
                                                "<polylist count=\"1\"><input semantic=\"VERTEX\" source=\"#A-vtx\" "
                                                "offset=\"0\"/><p>0 1 2</p></polylist>\n")),
                              "cow.dae"),
                    "cow.dae:12: <polylist> has no <vcount>");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", kSquare,
                                                "<triangles count=\"1\"><input semantic=\"NORMAL\" source=\"#n\" "
                                                "offset=\"0\"/><p>0 1 2</p></triangles>\n")),
                              "cow.dae"),
                    "cow.dae:12: <triangles> has no <input semantic=\"VERTEX\">");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", kSquare,
                                                "<triangles count=\"1\">\n<input source=\"#A-vtx\" offset=\"0\"/>"
                                                "<p>0 1 2</p></triangles>\n")),
                              "cow.dae"),
                    "cow.dae:13: <input> has no semantic attribute");
  EXPECT_FILE_ERROR(
      parse_dae(document(geometry("A", kSquare,
                                  "<triangles count=\"1\">\n<input semantic=\"VERTEX\" source=\"#A-vtx\"/>"
                                  "<p>0 1 2</p></triangles>\n")),
                "cow.dae"),
      "cow.dae:13: <input semantic=\"VERTEX\"> has no offset");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", kSquare,
                                                "<triangles count=\"1\">\n<input semantic=\"VERTEX\" source=\"#B-vtx\" "
                                                "offset=\"0\"/><p>0 1 2</p></triangles>\n")),
                              "cow.dae"),
                    "cow.dae:13:", "refers to \"#B-vtx\"");
  EXPECT_FILE_ERROR(parse_dae(document(geometry("A", kSquare,
                                                "<polygons count=\"1\"><input semantic=\"VERTEX\" source=\"#A-vtx\" "
                                                "offset=\"0\"/>\n<ph><p>0 1 2</p><h>3</h></ph></polygons>\n")),
                              "cow.dae"),
                    "cow.dae:13: polygons with holes (<ph>) are not supported");
}

TEST(Dae, RefusesBadSourcesAndAccessors) {
  const std::string tri =
      "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/><p>0 1 2</p></triangles>\n";
  const auto with_source = [&](const std::string& source, const std::string& vertices_input) {
    return document("<geometry id=\"G\"><mesh>\n" + source + "\n<vertices id=\"G-vtx\">\n" + vertices_input +
                    "\n</vertices>\n" + tri + "</mesh></geometry>\n");
  };
  const std::string position_input = "<input semantic=\"POSITION\" source=\"#G-pos\"/>";
  const std::string array = "<float_array count=\"9\">0 0 0 1 0 0 0 1 0</float_array>";
  EXPECT_FILE_ERROR(parse_dae(with_source("<source id=\"G-pos\">" + array + "</source>", ""), "s.dae"),
                    "s.dae:6: <vertices> has no <input semantic=\"POSITION\">");
  EXPECT_FILE_ERROR(parse_dae(with_source("<source id=\"other\">" + array + "</source>", position_input), "s.dae"),
                    "s.dae:7: <input> refers to \"#G-pos\", which is not a <source> of this <mesh>");
  EXPECT_FILE_ERROR(parse_dae(with_source("<source id=\"G-pos\"></source>", position_input), "s.dae"),
                    "s.dae:5: <source> of positions has no <float_array>");
  EXPECT_FILE_ERROR(
      parse_dae(with_source("<source id=\"G-pos\">" + array +
                                "\n<technique_common><accessor count=\"4\" stride=\"3\"/></technique_common></source>",
                            position_input),
                "s.dae"),
      "s.dae:6: <accessor> reads 12 numbers (count=4 stride=3 offset=0), but <float_array> holds 9");
  EXPECT_FILE_ERROR(
      parse_dae(with_source("<source id=\"G-pos\">" + array +
                                "\n<technique_common><accessor count=\"3\" stride=\"2\"/></technique_common></source>",
                            position_input),
                "s.dae"),
      "s.dae:6: <accessor> stride 2 is too small");
  EXPECT_FILE_ERROR(
      parse_dae(with_source("<source id=\"G-pos\">" + array +
                                "\n<technique_common><accessor count=\"99999999999\"/></technique_common></source>",
                            position_input),
                "s.dae"),
      "s.dae:6: <accessor> attribute count=\"99999999999\" must be a whole number from 0 to");
  EXPECT_FILE_ERROR(parse_dae(document("<geometry id=\"G\"><mesh>\n" + tri + "</mesh></geometry>"), "s.dae"),
                    "s.dae:4: <mesh> has no <vertices>");
}

TEST(Dae, RefusesBadScenes) {
  const std::string tri = geometry("T", "1 0 0  0 1 0  0 0 1", triangles("T", "0 0 1 0 2 0", "1"));
  // The header takes lines 1-3 and the geometry 4-18; </library_geometries> is 19,
  // <library_visual_scenes> 20, <visual_scene> 21, so each <node> below starts on line 22.
  EXPECT_FILE_ERROR(parse_dae(document(tri, "<node>\n<instance_geometry url=\"#nope\"/></node>\n"), "n.dae"),
                    "n.dae:23: <instance_geometry> refers to \"#nope\", which is not a <geometry>");
  EXPECT_FILE_ERROR(
      parse_dae(document(tri, "<node>\n<matrix>1 0 0</matrix><instance_geometry url=\"#T\"/></node>\n"), "n.dae"),
      "n.dae:23: <matrix> holds 3 numbers, expected 16");
  EXPECT_FILE_ERROR(parse_dae(document(tri, "<node>\n<translate>0 nan 0</translate></node>\n"), "n.dae"),
                    "n.dae:23: a number in <translate> must be a finite number");
  EXPECT_FILE_ERROR(
      parse_dae(document(tri, "<node>\n<skew>45 1 0 0 0 1 0</skew>\n<instance_geometry url=\"#T\"/></node>\n"),
                "n.dae"),
      "n.dae:23: <skew> transforms are not supported");
  EXPECT_FILE_ERROR(
      parse_dae(document(tri, "<node>\n<rotate>0 0 0 90</rotate>\n<instance_geometry url=\"#T\"/></node>\n"), "n.dae"),
      "n.dae:23: <rotate> has a zero-length axis");
  EXPECT_FILE_ERROR(parse_dae(document(tri,
                                       "<node>\n<scale>1e300 1 1</scale><scale>1e300 1 1</scale>\n"
                                       "<instance_geometry url=\"#T\"/></node>\n"),
                              "n.dae"),
                    "n.dae:24: the node's transform moves vertex 0 of <geometry id=\"T\"> to a non-finite position");
  EXPECT_FILE_ERROR(parse_dae(document(tri, "<node>\n<instance_geometry/></node>\n"), "n.dae"),
                    "n.dae:23: <instance_geometry> has no url attribute");
  std::string bad_scene = document(tri, "<node/>\n");
  bad_scene.replace(bad_scene.find("url=\"#Scene\""), 12, "url=\"#Other\"");
  EXPECT_FILE_ERROR(parse_dae(bad_scene, "n.dae"), "n.dae:", "refers to \"#Other\", which is not a <visual_scene>");
}

// `document(...)` with an <asset> right after <COLLADA>, holding `asset_body`.
std::string with_asset(const std::string& asset_body) {
  std::string text = document(geometry("T", "0 0 0 1 0 0 0 1 0", triangles("T", "0 0 1 0 2 0", "1")));
  return text.insert(text.find("<library_geometries>"), "<asset>\n" + asset_body + "</asset>\n");
}

TEST(Dae, ReadsTheUpAxisTagAndTheAuthoringTool) {
  const std::pair<const char*, UpAxis> tags[] = {{"X_UP", UpAxis::X}, {"Y_UP", UpAxis::Y}, {"Z_UP", UpAxis::Z}};
  for (const auto& [tag, axis] : tags) {
    SCOPED_TRACE(tag);
    const DaeFile file = parse_dae_file(with_asset(std::string("<up_axis>") + tag + "</up_axis>\n"), "u.dae");
    EXPECT_TRUE(file.asset.up_axis_tagged);
    EXPECT_EQ(file.asset.up_axis, axis);
    EXPECT_EQ(file.mesh.num_faces(), 1u);
  }
  const DaeFile spaced = parse_dae_file(
      with_asset("<contributor>\n<author>someone</author>\n<authoring_tool>\n  Blender 2.72.0  \n</authoring_tool>\n"
                 "</contributor>\n<contributor><authoring_tool>second</authoring_tool></contributor>\n"
                 "<up_axis>\n Z_UP\n</up_axis>\n"),
      "u.dae");
  EXPECT_EQ(spaced.asset.up_axis, UpAxis::Z);
  EXPECT_EQ(spaced.asset.authoring_tool, "Blender 2.72.0");  // trimmed, from the first contributor that names one
}

TEST(Dae, WithoutAnUpAxisTagTheAssetIsColladasDefault) {
  for (const std::string& text : {with_asset("<unit meter=\"1\"/>\n"),
                                  document(geometry("T", "0 0 0 1 0 0 0 1 0", triangles("T", "0 0 1 0 2 0", "1")))}) {
    const DaeFile file = parse_dae_file(text, "u.dae");
    EXPECT_FALSE(file.asset.up_axis_tagged);
    EXPECT_EQ(file.asset.up_axis, UpAxis::Y);
    EXPECT_EQ(file.asset.authoring_tool, "");
  }
}

TEST(Dae, RefusesAnUpAxisTagItDoesNotKnowWithItsLine) {
  // The header takes lines 1-2, <asset> line 3, so <up_axis> is line 4.
  EXPECT_FILE_ERROR(parse_dae(with_asset("<up_axis>W_UP</up_axis>\n"), "u.dae"),
                    "u.dae:4: <up_axis> is \"W_UP\", expected X_UP, Y_UP or Z_UP");
  EXPECT_FILE_ERROR(parse_dae(with_asset("<up_axis/>\n"), "u.dae"), "u.dae:4: <up_axis> is \"\",");
}

}  // namespace
}  // namespace meshedit
