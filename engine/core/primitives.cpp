// Procedural meshes (see primitives.h for the numbering of each shape).
#include "core/primitives.h"

#include <cmath>
#include <numbers>

namespace meshedit {

PolygonMesh make_tetrahedron() {
  PolygonMesh m;
  m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.add_face({0, 1, 2});
  m.add_face({0, 3, 1});
  m.add_face({0, 2, 3});
  m.add_face({1, 3, 2});
  return m;
}

namespace {
PolygonMesh cube_vertices() {
  PolygonMesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex({(i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5});
  return m;
}
// The six sides as counter-clockwise quads seen from outside.
constexpr uint32_t kCubeQuads[6][4] = {
    {0, 2, 3, 1},  // z = -0.5
    {4, 5, 7, 6},  // z = +0.5
    {0, 1, 5, 4},  // y = -0.5
    {2, 6, 7, 3},  // y = +0.5
    {0, 4, 6, 2},  // x = -0.5
    {1, 3, 7, 5},  // x = +0.5
};
}  // namespace

PolygonMesh make_cube() {
  PolygonMesh m = cube_vertices();
  for (const auto& q : kCubeQuads) {
    m.add_face({q[0], q[1], q[2]});
    m.add_face({q[0], q[2], q[3]});
  }
  return m;
}

PolygonMesh make_cube_quads() {
  PolygonMesh m = cube_vertices();
  for (const auto& q : kCubeQuads) m.add_face({q[0], q[1], q[2], q[3]});
  return m;
}

PolygonMesh make_icosahedron() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  const double s = 1.0 / std::sqrt(1.0 + phi * phi);
  PolygonMesh m;
  m.positions = {{-1, phi, 0},  {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi},  {0, 1, phi},
                 {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1},  {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
  for (auto& p : m.positions) p *= s;
  const uint32_t faces[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (const auto& f : faces) m.add_face({f[0], f[1], f[2]});
  return m;
}

PolygonMesh make_grid(uint32_t nx, uint32_t ny) {
  PolygonMesh m;
  for (uint32_t j = 0; j <= ny; ++j)
    for (uint32_t i = 0; i <= nx; ++i) m.add_vertex({double(i), double(j), 0.0});
  auto id = [nx](uint32_t i, uint32_t j) { return j * (nx + 1) + i; };
  for (uint32_t j = 0; j < ny; ++j) {
    for (uint32_t i = 0; i < nx; ++i) {
      m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return m;
}

PolygonMesh make_fan(uint32_t n) {
  PolygonMesh m;
  m.add_vertex({0, 0, 0});
  for (uint32_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    m.add_vertex({std::cos(a), std::sin(a), 0.0});
  }
  for (uint32_t i = 0; i < n; ++i) m.add_face({0, 1 + i, 1 + (i + 1) % n});
  return m;
}

PolygonMesh make_torus(uint32_t rings, uint32_t sides) {
  PolygonMesh m;
  const double major = 1.0, minor = 0.35;
  m.positions.reserve(size_t(rings) * sides);
  for (uint32_t i = 0; i < rings; ++i) {
    const double u = 2.0 * std::numbers::pi * i / rings;
    for (uint32_t j = 0; j < sides; ++j) {
      const double v = 2.0 * std::numbers::pi * j / sides;
      const double r = major + minor * std::cos(v);
      m.add_vertex({r * std::cos(u), r * std::sin(u), minor * std::sin(v)});
    }
  }
  auto id = [sides](uint32_t i, uint32_t j) { return i * sides + j; };
  m.indices.reserve(size_t(rings) * sides * 6);
  m.face_offsets.reserve(size_t(rings) * sides * 2 + 1);
  for (uint32_t i = 0; i < rings; ++i) {
    const uint32_t i1 = (i + 1) % rings;
    for (uint32_t j = 0; j < sides; ++j) {
      const uint32_t j1 = (j + 1) % sides;
      m.add_face({id(i, j), id(i1, j), id(i1, j1)});
      m.add_face({id(i, j), id(i1, j1), id(i, j1)});
    }
  }
  return m;
}

PolygonMesh make_torus_with_faces(uint32_t faces) {
  // faces = 2 * rings * sides with rings = 2 * sides  =>  sides = sqrt(faces / 4)
  const auto sides = static_cast<uint32_t>(std::max(3.0, std::round(std::sqrt(faces / 4.0))));
  return make_torus(2 * sides, sides);
}

}  // namespace meshedit
