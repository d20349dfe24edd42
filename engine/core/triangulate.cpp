// Ear clipping in each polygon's Newell plane (triangulate.h), and triangulating whole meshes with it.
#include "core/triangulate.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <unordered_set>

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
  return triangulate_polygon(corners, nullptr, used_fan);
}

std::vector<uint32_t> triangulate_polygon(std::span<const glm::dvec3> corners, const DiagonalAllowed& allowed,
                                          bool* used_fan) {
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
    // The best-shaped ear whose diagonal is allowed; failing that, the best-shaped ear.
    size_t best = m, best_allowed = m;
    double best_shape = -1.0, best_allowed_shape = -1.0;
    for (size_t k = 0; k < m; ++k) {
      if (!is_ear(k)) continue;
      const uint32_t a = left[(k + m - 1) % m], c = left[(k + 1) % m];
      const double s = shape(p[a], p[left[k]], p[c]);
      if (s > best_shape) best = k, best_shape = s;
      const bool ok = !allowed || allowed(a, c);
      if (ok && s > best_allowed_shape) best_allowed = k, best_allowed_shape = s;
      if (m > kBestEarLimit && ok) break;
    }
    if (best_allowed != m) best = best_allowed;
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
  // Every edge the mesh has, and each diagonal once placed: a diagonal along one of them would give that edge more
  // than two faces (two quads sharing three corners, cut along the same diagonal, make one triangle twice).
  const auto key = [](uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | std::max(a, b); };
  std::unordered_set<uint64_t> edges;
  for (size_t f = 0; f < polygons.num_faces(); ++f) {
    const std::span<const uint32_t> face = polygons.face(f);
    for (size_t i = 0; i < face.size(); ++i) edges.insert(key(face[i], face[(i + 1) % face.size()]));
  }
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
    const std::vector<uint32_t> triangles = triangulate_polygon(
        corners, [&](uint32_t a, uint32_t c) { return !edges.contains(key(face[a], face[c])); }, &fan);
    for (size_t t = 0; t < triangles.size(); t += 3) {
      const uint32_t a = face[triangles[t]], b = face[triangles[t + 1]], c = face[triangles[t + 2]];
      out.add_face({a, b, c});
      edges.insert(key(a, b)), edges.insert(key(b, c)), edges.insert(key(c, a));
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
    mesh.replace_with(std::move(triangles));
    return {Check::yes(), report};
  } catch (const MeshError& e) {
    return {Check::no(std::string("cannot triangulate: ") + e.what()), {}};
  }
}

}  // namespace meshedit
