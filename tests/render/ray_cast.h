// Exact CPU ray casts for the picking tests: which face a ray through a pixel meets first, checked against what
// the renderer's id pass (picking_test) or a synthesised id window (pick_from_faces_test) gives.
#pragma once

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "core/halfedge_mesh.h"
#include "render/camera.h"
#include "render/mesh_geometry.h"

namespace meshedit::testing {

// Distance along the ray to triangle (a, b, c), if it hits (Moller-Trumbore).
inline std::optional<double> hit(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(ray.direction, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return std::nullopt;
  const glm::dvec3 t = ray.origin - a;
  const double u = glm::dot(t, p) / det;
  const glm::dvec3 q = glm::cross(t, e1);
  const double v = glm::dot(ray.direction, q) / det;
  const double s = glm::dot(e2, q) / det;
  if (u < 0 || v < 0 || u + v > 1 || s <= 0) return std::nullopt;
  return s;
}

// The face (a triangle mesh's) that an exact ray cast through pixel (x, y)'s centre meets first.
inline ElementRef cast(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport, int x, int y) {
  const Ray ray = camera.ray({x + 0.5, y + 0.5}, viewport);
  ElementRef best;
  double nearest = 1e300;
  for (FaceId f : mesh.faces()) {
    const auto corners = face_corners(mesh, f);
    if (!corners || corners->size() != 3) continue;
    if (auto s = hit(ray, (*corners)[0], (*corners)[1], (*corners)[2]); s && *s < nearest) {
      nearest = *s;
      best = f;
    }
  }
  return best;
}

// The live edge joining a and b, or an invalid id.
inline EdgeId edge_between(const HalfedgeMesh& mesh, VertexId a, VertexId b) {
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    const VertexId u = mesh.vertex(h), v = mesh.vertex(mesh.twin(h));
    if ((u == a && v == b) || (u == b && v == a)) return e;
  }
  return EdgeId();
}

}  // namespace meshedit::testing
