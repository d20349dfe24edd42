// Wrong Loop weights and misplaced positions, read from positions (see loop_position_diagnosis.h).
#include "exercise/internal/loop_position_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "core/translation.h"
#include "core/value_format.h"
#include "exercise/internal/loop_diagnosis_support.h"

namespace meshedit {
namespace {

using namespace loop_diagnosis;

double loop_original_u(size_t n) {
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * std::numbers::pi / double(n));
  return (5.0 / 8.0 - c * c) / double(n);
}

// The original neighbours of v in `mesh` and their sum; nullopt when v is on the boundary or its fan is broken.
struct Ring {
  size_t n = 0;
  glm::dvec3 sum{0.0};
};
std::optional<Ring> interior_ring(const HalfedgeMesh& mesh, VertexId v) {
  Ring ring;
  bool boundary = false;
  const bool ok = mesh.for_each_outgoing(v, [&](HalfedgeId h) {
    boundary = boundary || mesh.face(h).is_boundary();
    ++ring.n;
    ring.sum += mesh.position(mesh.vertex(mesh.twin(h)));
  });
  if (!ok || boundary || ring.n == 0) return std::nullopt;
  return ring;
}

std::string vertex_weight_message(const HalfedgeMesh& before, const HalfedgeMesh& yours, const HalfedgeMesh& reference,
                                  double tolerance) {
  VertexId first;
  size_t first_n = 0, count = 0;
  double first_u = 0.0;
  for (VertexId v : before.vertices()) {
    if (!yours.alive(v) || !reference.alive(v)) continue;
    const glm::dvec3& q = yours.position(v);
    if (close(q, reference.position(v), tolerance)) continue;
    const std::optional<Ring> ring = interior_ring(before, v);
    if (!ring) continue;
    const glm::dvec3& p = before.position(v);
    const glm::dvec3 direction = ring->sum - double(ring->n) * p;
    const double length2 = glm::dot(direction, direction);
    if (!(length2 > tolerance * tolerance)) continue;
    const double u = glm::dot(q - p, direction) / length2;
    if (!(std::abs(u) * std::sqrt(length2) > tolerance)) continue;  // unmoved: told elsewhere
    if (!close(q, p + u * direction, tolerance)) continue;
    if (count++ == 0) {
      first = v;
      first_n = ring->n;
      first_u = u;
    }
  }
  if (count == 0) return "";
  const double want = course_u(first_n);
  MessageParts parts = {{"vertex", format_id(first)},
                        {"degree", std::to_string(first_n)},
                        {"u", format_number(first_u)},
                        {"count", std::to_string(count)},
                        {"formula", first_n == 3 ? std::string("3/16") : "3 / (8 * " + std::to_string(first_n) + ")"},
                        {"want", format_number(want)}};
  parts.emplace_back(
      "head", count > 1 ? tr_format("your original vertex {vertex} (degree {degree}) moved as if u = {u} "
                                    "({count} original vertices moved by a wrong weight)",
                                    parts)
                        : tr_format("your original vertex {vertex} (degree {degree}) moved as if u = {u}", parts));
  if (std::abs(first_u - loop_original_u(first_n)) <= 1e-9) {
    parts.emplace_back("why", tr("yours is Loop's original weight beta / n; the course uses 3/16 for degree 3, else "
                                 "3 / (8 n)"));
  } else if (first_n == 3 && std::abs(first_u - 3.0 / 24.0) <= 1e-12) {
    parts.emplace_back("why", tr("yours is 3 / (8 n) with n = 3: degree 3 is the exception, u = 3/16"));
  } else {
    parts.emplace_back("why", tr("3/16 for degree 3, else 3 / (8 n)"));
  }
  return tr_format(
      "{head}; the course's u for degree {degree} is {formula} = {want} ({why}): the new position is "
      "(1 - n u) p + u (sum of the neighbours)",
      parts);
}

struct EdgeRule {
  const char* what;  // how the message names the wrong rule
  double ab, cd;     // weights of a + b and c + d
  size_t count = 0;
  std::string example;
};

std::string edge_weight_message(const HalfedgeMesh& before, const HalfedgeMesh& yours, double tolerance,
                                bool origin_explained) {
  EdgeRule rules[] = {{"the midpoint of the edge it splits, (a + b) / 2", 0.5, 0.0},
                      {"1/8 (a + b) + 3/8 (c + d): the weights are swapped", 1.0 / 8.0, 3.0 / 8.0},
                      {"the average of the four corners, (a + b + c + d) / 4", 0.25, 0.25}};
  const uint32_t old_capacity = before.vertex_capacity();
  for (VertexId w : yours.vertices()) {
    if (w.index < old_capacity) continue;
    if (origin_explained && close(yours.position(w), glm::dvec3(0.0), tolerance)) continue;
    const std::vector<VertexId> old_neighbours = original_neighbours(before, yours, w);
    bool done = false;
    for (size_t i = 0; i < old_neighbours.size() && !done; ++i) {
      for (size_t j = i + 1; j < old_neighbours.size() && !done; ++j) {
        const VertexId a = old_neighbours[i], b = old_neighbours[j];
        const HalfedgeId h = halfedge_between(before, a, b);
        if (!h.valid() || before.face(h).is_boundary() || before.face(before.twin(h)).is_boundary()) continue;
        const VertexId c = before.vertex(before.next(before.next(h)));
        const VertexId d = before.vertex(before.next(before.next(before.twin(h))));
        const glm::dvec3 ab = before.position(a) + before.position(b);
        const glm::dvec3 cd = before.position(c) + before.position(d);
        const glm::dvec3 course = 3.0 / 8.0 * ab + 1.0 / 8.0 * cd;
        const glm::dvec3& q = yours.position(w);
        if (close(q, course, tolerance)) {
          done = true;
          continue;
        }
        for (EdgeRule& rule : rules) {
          if (!close(q, rule.ab * ab + rule.cd * cd, tolerance)) continue;
          if (rule.count++ == 0) {
            rule.example = tr_format("{vertex} on the edge {edge} (opposite corners {c} {d})",
                                     {{"vertex", format_id(w)},
                                      {"edge", format_id(a) + "-" + format_id(b)},
                                      {"c", format_id(c)},
                                      {"d", format_id(d)}});
          }
          done = true;
          break;
        }
      }
    }
  }
  const EdgeRule* worst = nullptr;
  for (const EdgeRule& rule : rules) {
    if (rule.count > 0 && (!worst || rule.count > worst->count)) worst = &rule;
  }
  if (!worst) return "";
  return tr_format(
      "{count} of your new vertices, e.g. {example}, are at {rule}; the course's edge point for an "
      "interior edge is 3/8 (a + b) + 1/8 (c + d), with c and d the corners opposite the edge (the "
      "midpoint is the rule for boundary edges only)",
      {{"count", std::to_string(worst->count)}, {"example", worst->example}, {"rule", tr(worst->what)}});
}

// Original vertices of yours at the reference's position of a new vertex (sorted by x, searched by x).
std::string misplaced_message(const HalfedgeMesh& before, const HalfedgeMesh& yours, const HalfedgeMesh& reference,
                              double tolerance) {
  const uint32_t old_capacity = before.vertex_capacity();
  std::vector<std::pair<glm::dvec3, VertexId>> edge_points;
  for (VertexId w : reference.vertices()) {
    if (w.index >= old_capacity) edge_points.emplace_back(reference.position(w), w);
  }
  std::sort(edge_points.begin(), edge_points.end(), [](const auto& a, const auto& b) { return a.first.x < b.first.x; });
  size_t count = 0;
  std::string example;
  for (VertexId v : before.vertices()) {
    if (!yours.alive(v) || !reference.alive(v)) continue;
    const glm::dvec3& q = yours.position(v);
    if (close(q, reference.position(v), tolerance)) continue;
    auto it = std::lower_bound(edge_points.begin(), edge_points.end(), q.x - tolerance,
                               [](const auto& e, double x) { return e.first.x < x; });
    for (; it != edge_points.end() && it->first.x <= q.x + tolerance; ++it) {
      if (!close(q, it->first, tolerance)) continue;
      if (count++ == 0) {
        example =
            tr_format("{vertex} at {position}, where the reference puts the new vertex {new}",
                      {{"vertex", format_id(v)}, {"position", format_position(q)}, {"new", format_id(it->second)}});
      }
      break;
    }
  }
  if (count == 0) return "";
  return tr_format(
      "{count} of your original vertices sit where the reference puts new vertices, e.g. {example}: a "
      "position computed for a new vertex (step 2) was written to an original one; keep it under the new "
      "vertex's own id (m.id, from the split that made m)",
      {{"count", std::to_string(count)}, {"example", example}});
}

}  // namespace

std::vector<std::string> diagnose_loop_positions(const HalfedgeMesh& before, const HalfedgeMesh& yours,
                                                 const HalfedgeMesh& reference, double tolerance,
                                                 bool origin_explained) {
  std::vector<std::string> out;
  if (std::string m = misplaced_message(before, yours, reference, tolerance); !m.empty()) out.push_back(m);
  if (std::string m = vertex_weight_message(before, yours, reference, tolerance); !m.empty()) out.push_back(m);
  if (std::string m = edge_weight_message(before, yours, tolerance, origin_explained); !m.empty()) out.push_back(m);
  return out;
}

}  // namespace meshedit
