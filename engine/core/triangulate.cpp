// Ear clipping in each polygon's Newell plane (triangulate.h), and triangulating whole meshes with it.
#include "core/triangulate.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/mesh_build.h"
#include "core/mesh_error.h"

namespace meshedit {
namespace {

// Past this many corners the first ear is taken instead of the best-shaped one (choosing is quadratic per ear).
constexpr size_t kBestEarLimit = 48;

double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The corners in 2D, seen from the side the normal points to (so the polygon's own order is counter-clockwise).
std::vector<glm::dvec2> project(std::span<const glm::dvec3> corners, const glm::dvec3& normal) {
  glm::dvec3 n = normal;
  if (glm::length(n) == 0.0) n = glm::dvec3(0, 0, 1);
  n = glm::normalize(n);
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
  const glm::dvec3 v = glm::cross(n, u);  // u x v = n: counter-clockwise seen from n
  std::vector<glm::dvec2> points;
  points.reserve(corners.size());
  for (const glm::dvec3& p : corners) points.emplace_back(glm::dot(p, u), glm::dot(p, v));
  return points;
}

// Whether p lies inside or on triangle abc (counter-clockwise).
bool in_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double eps) {
  return cross2(a, b, p) >= -eps && cross2(b, c, p) >= -eps && cross2(c, a, p) >= -eps;
}

// How well shaped a triangle is: 0 for a sliver, largest for an equilateral one.
double shape(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const double sum = glm::dot(b - a, b - a) + glm::dot(c - b, c - b) + glm::dot(a - c, a - c);
  return sum > 0 ? cross2(a, b, c) / sum : 0.0;
}

}  // namespace

glm::dvec3 newell_normal(std::span<const glm::dvec3> corners) {
  glm::dvec3 n(0.0);
  for (size_t i = 0; i < corners.size(); ++i) {
    const glm::dvec3& a = corners[i];
    const glm::dvec3& b = corners[(i + 1) % corners.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

std::vector<uint32_t> triangulate_polygon(std::span<const glm::dvec3> corners, bool* used_fan) {
  if (used_fan) *used_fan = false;
  std::vector<uint32_t> triangles;
  const size_t n = corners.size();
  if (n < 3) return triangles;
  triangles.reserve(3 * (n - 2));
  if (n == 3) return {0, 1, 2};
  const std::vector<glm::dvec2> p = project(corners, newell_normal(corners));
  glm::dvec2 low = p[0], high = p[0];
  for (const glm::dvec2& q : p) low = glm::min(low, q), high = glm::max(high, q);
  const double size = std::max(high.x - low.x, high.y - low.y);
  const double eps = 1e-12 * size * size;  // areas below this count as zero

  std::vector<uint32_t> left(n);  // the corners not clipped yet, in order
  for (uint32_t i = 0; i < n; ++i) left[i] = i;
  auto is_ear = [&](size_t k) {
    const size_t m = left.size();
    const uint32_t a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
    if (cross2(p[a], p[b], p[c]) <= eps) return false;  // reflex or flat: its triangle would be flipped or empty
    for (uint32_t other : left) {
      if (other == a || other == b || other == c) continue;
      if (p[other] == p[a] || p[other] == p[b] || p[other] == p[c]) continue;  // a corner the polygon revisits
      if (in_triangle(p[other], p[a], p[b], p[c], eps)) return false;
    }
    return true;
  };
  while (left.size() > 3) {
    const size_t m = left.size();
    size_t best = m;
    double best_shape = -1.0;
    for (size_t k = 0; k < m; ++k) {
      if (!is_ear(k)) continue;
      const double s = shape(p[left[(k + m - 1) % m]], p[left[k]], p[left[(k + 1) % m]]);
      if (s > best_shape) best = k, best_shape = s;
      if (m > kBestEarLimit) break;
    }
    if (best == m) {  // no ear: cut what is left as a fan from its first corner
      if (used_fan) *used_fan = true;
      for (size_t k = 1; k + 1 < m; ++k) triangles.insert(triangles.end(), {left[0], left[k], left[k + 1]});
      return triangles;
    }
    triangles.insert(triangles.end(), {left[(best + m - 1) % m], left[best], left[(best + 1) % m]});
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(best));
  }
  triangles.insert(triangles.end(), {left[0], left[1], left[2]});
  return triangles;
}

PolygonMesh triangulate(const PolygonMesh& polygons, TriangulationReport* report) {
  PolygonMesh out;
  out.positions = polygons.positions;
  out.indices.reserve(polygons.indices.size() * 3 / 2);
  out.face_offsets.reserve(polygons.num_faces() * 2 + 1);
  TriangulationReport counts;
  std::vector<glm::dvec3> corners;
  for (size_t f = 0; f < polygons.num_faces(); ++f) {
    const std::span<const uint32_t> face = polygons.face(f);
    bool in_range = true;
    for (uint32_t i : face) in_range = in_range && i < polygons.num_vertices();
    if (face.size() <= 3 || !in_range) {  // not a polygon to split (or a bad one, for the builder to report)
      out.add_face(face);
      continue;
    }
    corners.clear();
    for (uint32_t i : face) corners.push_back(polygons.positions[i]);
    bool fan = false;
    const std::vector<uint32_t> triangles = triangulate_polygon(corners, &fan);
    for (size_t t = 0; t < triangles.size(); t += 3) {
      out.add_face({face[triangles[t]], face[triangles[t + 1]], face[triangles[t + 2]]});
    }
    ++counts.polygons_split;
    counts.triangles_made += triangles.size() / 3;
    counts.fan_fallbacks += fan ? 1 : 0;
  }
  if (report) *report = counts;
  return out;
}

OpResult<TriangulationReport> triangulate_mesh(HalfedgeMesh& mesh) {
  bool all_triangles = true;
  for (FaceId f : mesh.faces()) all_triangles = all_triangles && mesh.degree(f) == 3;
  if (all_triangles) return {Check::yes(), {}};
  try {
    TriangulationReport report;
    HalfedgeMesh triangles = build_halfedge_mesh(triangulate(to_polygon_mesh(mesh), &report));
    mesh = std::move(triangles);
    return {Check::yes(), report};
  } catch (const MeshError& e) {
    return {Check::no(std::string("cannot triangulate: ") + e.what()), {}};
  }
}

}  // namespace meshedit
