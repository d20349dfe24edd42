// Repair on thousands of random small polygon soups (fixed seeds): strips and grids glued into annuli, Moebius
// strips, tori, Klein bottles and projective planes, fans around one vertex, and plain random faces, each with faces
// flipped, shuffled, welded, repeated and broken at random. Whatever comes in, the repaired polygons build and
// validate, repairing them again changes nothing, every face is an input face with its positions (in order or
// reversed), every spot is an id of the built mesh, and each cut edge is two boundary edges at the same positions.
// Deeper runs: MESHEDIT_FUZZ_SCALE=20 multiplies the count, MESHEDIT_FUZZ_SEED=n shifts the seed (best in a
// -fsanitize=address,undefined build).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/validate.h"

namespace meshedit {
namespace {

using Random = std::mt19937;  // raw output only, so a seed gives the same soups on every platform

uint64_t from_environment(const char* name, uint64_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::strtoull(value, nullptr, 10) : fallback;
}

uint32_t below(Random& r, uint32_t n) { return r() % n; }

glm::dvec3 random_point(Random& r) {
  const auto coordinate = [&] { return double(below(r, 2001)) / 1000 - 1; };
  const double x = coordinate(), y = coordinate(), z = coordinate();
  return {x, y, z};
}

void add_random_positions(PolygonMesh& p, uint32_t count, Random& r) {
  for (uint32_t i = 0; i < count; ++i) p.add_vertex(random_point(r));
}

// How a grid's side is glued to the opposite one: not at all, straight (an annulus, a torus) or with a half twist
// (a Moebius strip, a Klein bottle).
enum class Glue { None, Straight, Twisted };

// A grid of columns x rows quads (vertex (i, j) for i <= columns, j <= rows), its side i = columns glued to i = 0
// as `across` says and its side j = rows to j = 0 as `along` says; each quad is kept or cut into two triangles.
PolygonMesh glued_grid(uint32_t columns, uint32_t rows, Glue across, Glue along, Random& r) {
  PolygonMesh p;
  add_random_positions(p, (columns + 1) * (rows + 1), r);
  const auto id = [&](uint32_t i, uint32_t j) {
    for (int pass = 0; pass < 3; ++pass) {
      if (i == columns && across != Glue::None) {
        i = 0;
        if (across == Glue::Twisted) j = along != Glue::None ? (rows - j) % rows : rows - j;
      }
      if (j == rows && along != Glue::None) {
        j = 0;
        if (along == Glue::Twisted) i = across != Glue::None ? (columns - i) % columns : columns - i;
      }
    }
    return i + j * (columns + 1);
  };
  for (uint32_t j = 0; j < rows; ++j) {
    for (uint32_t i = 0; i < columns; ++i) {
      const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      switch (below(r, 3)) {
        case 0: p.add_face({a, b, c, d}); break;
        case 1: {
          p.add_face({a, b, c});
          p.add_face({a, c, d});
          break;
        }
        default: {
          p.add_face({a, b, d});
          p.add_face({b, c, d});
          break;
        }
      }
    }
  }
  return p;
}

// One to three fans of triangles around vertex 0, each closed or open.
PolygonMesh fans(Random& r) {
  PolygonMesh p;
  p.add_vertex(random_point(r));
  const uint32_t count = 1 + below(r, 3);
  for (uint32_t fan = 0; fan < count; ++fan) {
    const uint32_t n = 3 + below(r, 5), first = static_cast<uint32_t>(p.num_vertices());
    add_random_positions(p, n, r);
    const bool closed = below(r, 2) == 0;
    for (uint32_t k = 0; k + (closed ? 0 : 1) < n; ++k) p.add_face({0, first + k, first + (k + 1) % n});
  }
  return p;
}

// Faces of random corners, a few of them out of range or with fewer than three corners.
PolygonMesh random_faces(Random& r) {
  PolygonMesh p;
  const uint32_t vertices = 3 + below(r, 9), faces = 1 + below(r, 16);
  add_random_positions(p, vertices, r);
  if (below(r, 3) == 0) {  // some on a grid of whole numbers: collinear and repeated positions, zero areas
    for (glm::dvec3& x : p.positions) {
      const double a = below(r, 3), b = below(r, 2);
      x = glm::dvec3(a, b, 0);
    }
  }
  for (uint32_t f = 0; f < faces; ++f) {
    std::vector<uint32_t> corners(below(r, 12) == 0 ? 1 + below(r, 2) : 3 + below(r, 3));
    for (uint32_t& c : corners) c = below(r, 40) == 0 ? vertices + below(r, 3) : below(r, vertices);
    p.add_face(corners);
  }
  return p;
}

// `p` with `q` appended and a few of q's vertices welded to p's.
PolygonMesh joined(const PolygonMesh& p, const PolygonMesh& q, Random& r) {
  PolygonMesh out = p;
  out.append(q);
  const uint32_t welds = below(r, 3);
  for (uint32_t k = 0; k < welds && p.num_vertices() > 0; ++k) {
    const uint32_t from = static_cast<uint32_t>(p.num_vertices()) + below(r, uint32_t(q.num_vertices()));
    const uint32_t to = below(r, uint32_t(p.num_vertices()));
    for (uint32_t& i : out.indices) i = i == from ? to : i;
  }
  return out;
}

// Faces reversed, the face order shuffled, the vertices renumbered, vertices welded, faces repeated: each at random.
PolygonMesh disturbed(PolygonMesh p, Random& r) {
  const uint32_t flip_chance = std::vector<uint32_t>{0, 2, 10, 1000}[below(r, 4)];  // 1 in this many faces
  std::vector<std::vector<uint32_t>> faces;
  for (size_t f = 0; f < p.num_faces(); ++f) {
    faces.emplace_back(p.face(f).begin(), p.face(f).end());
    if (flip_chance && below(r, flip_chance) == 0) std::reverse(faces.back().begin(), faces.back().end());
  }
  if (below(r, 2) == 0) {
    for (size_t i = faces.size(); i > 1; --i) std::swap(faces[i - 1], faces[below(r, uint32_t(i))]);
  }
  const uint32_t n = static_cast<uint32_t>(p.num_vertices());
  std::vector<uint32_t> number(n);
  for (uint32_t v = 0; v < n; ++v) number[v] = v;
  if (below(r, 2) == 0) {
    for (uint32_t i = n; i > 1; --i) std::swap(number[i - 1], number[below(r, i)]);
  }
  if (n > 1 && below(r, 4) == 0) {  // a weld
    const uint32_t from = below(r, n), to = below(r, n);
    number[from] = number[to];
  }
  if (!faces.empty() && below(r, 6) == 0) {
    std::vector<uint32_t> repeat = faces[below(r, uint32_t(faces.size()))];
    std::rotate(repeat.begin(), repeat.begin() + 1, repeat.end());
    faces.push_back(repeat);
  }
  PolygonMesh out;
  out.positions.resize(n);
  for (uint32_t v = 0; v < n; ++v) out.positions[number[v]] = p.positions[v];
  for (auto& corners : faces) {
    for (uint32_t& c : corners) c = c < n ? number[c] : c;
    out.add_face(corners);
  }
  return out;
}

Glue random_glue(Random& r) { return Glue(below(r, 3)); }

// A grid of min_columns + below(columns) x min_rows + below(rows) quads glued as given (the sizes drawn first, in
// order).
PolygonMesh random_grid(uint32_t min_columns, uint32_t columns, uint32_t min_rows, uint32_t rows, Glue across,
                        Glue along, Random& r) {
  const uint32_t c = min_columns + below(r, columns);
  const uint32_t w = min_rows + below(r, rows);
  return glued_grid(c, w, across, along, r);
}

// One soup of the kind `kind % 6`.
PolygonMesh soup(uint32_t kind, Random& r) {
  switch (kind % 6) {
    case 0: return random_grid(3, 6, 1, 3, Glue::Twisted, Glue::None, r);      // Moebius strips
    case 1: return random_grid(3, 4, 3, 3, Glue::Twisted, Glue::Straight, r);  // Klein bottles
    case 2: {  // annuli, tori, Klein bottles, projective planes, plain grids
      const Glue across = random_glue(r), along = random_glue(r);
      return random_grid(1, 6, 1, 5, across, along, r);
    }
    case 3: return fans(r);
    case 4: return random_faces(r);
    default: {
      const Glue across = random_glue(r);
      const PolygonMesh a = random_grid(3, 3, 1, 2, across, Glue::None, r);
      const PolygonMesh b = below(r, 2) ? fans(r) : glued_grid(3, 1, Glue::Twisted, Glue::None, r);
      return joined(a, b, r);
    }
  }
}

std::vector<glm::dvec3> corner_positions(const PolygonMesh& p, size_t f) {
  std::vector<glm::dvec3> out;
  for (uint32_t v : p.face(f)) out.push_back(v < p.num_vertices() ? p.positions[v] : glm::dvec3(1e300));
  return out;
}

// Every repaired face is an input face, in order: the same corner positions, or those reversed after the first.
::testing::AssertionResult faces_are_input_faces(const PolygonMesh& in, const PolygonMesh& out) {
  size_t next = 0;
  for (size_t f = 0; f < out.num_faces(); ++f) {
    const std::vector<glm::dvec3> corners = corner_positions(out, f);
    std::vector<glm::dvec3> reversed = corners;
    std::reverse(reversed.begin() + 1, reversed.end());
    while (next < in.num_faces() && corner_positions(in, next) != corners && corner_positions(in, next) != reversed) {
      ++next;
    }
    if (next == in.num_faces()) return ::testing::AssertionFailure() << "output face " << f << " is no input face";
    ++next;
  }
  return ::testing::AssertionSuccess();
}

// Face f's halfedge from a to b or from b to a, or an invalid id.
HalfedgeId edge_in_face(const HalfedgeMesh& m, FaceId f, uint32_t a, uint32_t b) {
  HalfedgeId found;
  m.for_each_face_halfedge(f, [&](HalfedgeId h) {
    const uint32_t from = m.vertex(h).index, to = m.vertex(m.next(h)).index;
    if ((from == a && to == b) || (from == b && to == a)) found = h;
  });
  return found;
}

// Each spot is a live id of the built mesh; a cut's spots are one edge on each side, both boundary edges, at the
// same two positions.
void expect_spots_in(const RepairResult& r, const HalfedgeMesh& m) {
  ASSERT_EQ(r.report.spots.size(), r.report.changes.size());
  size_t cuts = 0;
  for (size_t i = 0; i < r.report.spots.size(); ++i) {
    const RepairSpots& s = r.report.spots[i];
    SCOPED_TRACE(r.report.changes[i]);
    for (uint32_t v : s.vertices) ASSERT_TRUE(v < m.vertex_capacity() && m.alive(VertexId(v)));
    for (uint32_t f : s.faces) ASSERT_TRUE(f < m.face_capacity() && m.alive(FaceId::face(f)));
    if (r.report.changes[i].find(" was cut: ") == std::string::npos) continue;
    ++cuts;
    ASSERT_EQ(s.vertices.size(), 4u);
    ASSERT_EQ(s.faces.size(), 2u);
    for (int side = 0; side < 2; ++side) {
      const HalfedgeId h = edge_in_face(m, FaceId::face(s.faces[side]), s.vertices[2 * side], s.vertices[2 * side + 1]);
      ASSERT_TRUE(h.valid()) << "side " << side;
      EXPECT_TRUE(m.face(m.twin(h)).is_boundary()) << "side " << side;
    }
    EXPECT_NE(s.vertices[0], s.vertices[2]);
    EXPECT_NE(s.vertices[1], s.vertices[3]);
    EXPECT_EQ(m.position(VertexId(s.vertices[0])), m.position(VertexId(s.vertices[2])));
    EXPECT_EQ(m.position(VertexId(s.vertices[1])), m.position(VertexId(s.vertices[3])));
  }
  EXPECT_EQ(cuts, r.report.cut_edges);
}

// How often each step changed something, to show that the soups reach every one.
struct Tally {
  size_t cut = 0, cut_moebius = 0, cut_klein = 0, split = 0, detached = 0, reversed = 0, dropped = 0, untouched = 0;
};

void check_one(const PolygonMesh& input, uint32_t kind, Tally& tally) {
  const RepairResult r = repair_polygons(input);
  HalfedgeMesh mesh;
  try {
    mesh = build_halfedge_mesh(r.polygons);
  } catch (const MeshError& e) {
    FAIL() << "repaired polygons do not build: " << e.what() << "\n" << ::testing::PrintToString(r.report.changes);
  }
  const ValidationReport valid = validate(mesh);
  ASSERT_TRUE(valid.ok()) << valid.summary();
  expect_spots_in(r, mesh);
  EXPECT_TRUE(faces_are_input_faces(input, r.polygons));
  const RepairResult again = repair_polygons(r.polygons);
  EXPECT_TRUE(again.report.empty()) << ::testing::PrintToString(again.report.changes);
  EXPECT_EQ(again.polygons.indices, r.polygons.indices);
  const RepairReport& report = r.report;
  tally.cut += report.cut_edges > 0;
  tally.cut_moebius += kind % 6 == 0 && report.cut_edges > 0;
  tally.cut_klein += kind % 6 == 1 && report.cut_edges > 0;
  tally.split += report.split_vertices > 0;
  tally.detached += report.detached_faces > 0;
  tally.reversed += report.reversed_faces > 0;
  tally.dropped += report.dropped_bad_faces + report.dropped_repeated_faces > 0;
  tally.untouched += report.empty();
}

TEST(MeshRepairProperty, RandomSoupsAlwaysBuildAndValidateAfterOneRepair) {
  const uint64_t iterations = 6000 * from_environment("MESHEDIT_FUZZ_SCALE", 1);
  const uint64_t seed = 2024 + from_environment("MESHEDIT_FUZZ_SEED", 0);
  Random random(static_cast<uint32_t>(seed));
  Tally tally;
  for (uint64_t i = 0; i < iterations; ++i) {
    const uint32_t kind = static_cast<uint32_t>(i);
    const PolygonMesh input = disturbed(soup(kind, random), random);
    SCOPED_TRACE("soup " + std::to_string(i) + " (seed " + std::to_string(seed) + ")");
    check_one(input, kind, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf(
      "%llu soups: %zu cut, %zu with a bow-tie split, %zu detached, %zu reversed, %zu dropped faces, "
      "%zu untouched\n",
      static_cast<unsigned long long>(iterations), tally.cut, tally.split, tally.detached, tally.reversed,
      tally.dropped, tally.untouched);
  // Every step is reached, and most Moebius strips and Klein bottles are cut.
  for (size_t count : {tally.cut, tally.split, tally.detached, tally.reversed, tally.dropped, tally.untouched}) {
    EXPECT_GT(count, iterations / 100);
  }
  EXPECT_GT(tally.cut_moebius, iterations / 6 / 2);
  EXPECT_GT(tally.cut_klein, iterations / 6 / 2);
}

}  // namespace
}  // namespace meshedit
