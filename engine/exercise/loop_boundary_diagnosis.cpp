// The boundary rules of Loop subdivision against the interior rules applied there (see loop_boundary_diagnosis.h).
#include "exercise/internal/loop_boundary_diagnosis.h"

#include <optional>
#include <utility>

#include <glm/geometric.hpp>

#include "core/loop_rules.h"
#include "core/translation.h"
#include "core/value_format.h"
#include "core/vertex_ring.h"
#include "exercise/internal/loop_diagnosis_support.h"

namespace meshedit {
namespace {

using namespace loop_diagnosis;

// A boundary vertex's ring (its two neighbours along the boundary, and all of them); nullopt for a vertex with fewer
// than two boundary edges or a broken fan.
std::optional<VertexRing> boundary_ring(const HalfedgeMesh& mesh, VertexId v) {
  const VertexRing ring = vertex_ring(mesh, v);
  if (!ring.closed || ring.rim_count < 2) return std::nullopt;
  return ring;
}

// The first of `count` examples, and the message's tail.
struct Tally {
  size_t count = 0;
  std::string example;
  void add(const std::string& text) {
    if (count++ == 0) example = text;
  }
};

std::vector<std::string> vertex_messages(const HalfedgeMesh& before, const HalfedgeMesh& yours, double tolerance) {
  Tally interior, other;
  for (VertexId v : before.vertices()) {
    if (!yours.alive(v)) continue;
    const std::optional<VertexRing> ring = boundary_ring(before, v);
    if (!ring) continue;
    const glm::dvec3& p = before.position(v);
    const glm::dvec3 course =
        loop_rules::boundary_vertex(p, before.position(ring->rim[0]), before.position(ring->rim[1]));
    const glm::dvec3& q = yours.position(v);
    if (close(q, course, tolerance) || close(q, p, tolerance)) continue;  // right, or unmoved (told elsewhere)
    const size_t n = ring->valence;
    const double u = course_u(n);
    if (close(q, (1.0 - double(n) * u) * p + u * ring->neighbour_sum, tolerance)) {
      interior.add(tr_format("{vertex} ({count} neighbours, 2 of them along the boundary)",
                             {{"vertex", format_id(v)}, {"count", std::to_string(n)}}));
    } else {
      other.add(tr_format(
          "{vertex} at {position}, where the course puts it at {expected}",
          {{"vertex", format_id(v)}, {"position", format_position(q)}, {"expected", format_position(course)}}));
    }
  }
  const std::string rule =
      tr("a boundary vertex moves to 3/4 p + 1/8 (a + b), with a and b its two neighbours along the boundary (extra "
         "credit)");
  std::vector<std::string> out;
  if (interior.count > 0) {
    const MessageParts parts = {
        {"count", std::to_string(interior.count)}, {"example", interior.example}, {"rule", rule}};
    out.push_back(
        tr_format("{count} of your boundary vertices, e.g. {example}, moved by the interior rule (1 - n u) p "
                  "+ u (sum of all the neighbours); {rule}",
                  parts));
  }
  if (other.count > 0) {
    out.push_back(
        tr_format("{count} of your boundary vertices are not where the course puts them, e.g. {example}: "
                  "{rule}",
                  {{"count", std::to_string(other.count)}, {"example", other.example}, {"rule", rule}}));
  }
  return out;
}

// How a new vertex at `q` sits on the boundary edge from `inside`'s vertex to `outside`'s.
enum class EdgePlace { Midpoint, Across, WithoutD, Other };

EdgePlace edge_place(const HalfedgeMesh& before, HalfedgeId inside, HalfedgeId outside, const glm::dvec3& q,
                     double tolerance) {
  const glm::dvec3 a = before.position(before.vertex(inside)), b = before.position(before.vertex(outside));
  if (close(q, loop_rules::boundary_edge(a, b), tolerance)) return EdgePlace::Midpoint;
  const glm::dvec3 c = before.position(before.vertex(before.next(before.next(inside))));
  const glm::dvec3 d = before.position(before.vertex(before.next(before.next(outside))));
  if (close(q, loop_rules::interior_edge(a, b, c, d), tolerance)) return EdgePlace::Across;
  if (close(q, 0.375 * (a + b) + 0.125 * c, tolerance)) return EdgePlace::WithoutD;
  return EdgePlace::Other;
}

// Where the interior rule puts the new vertex of the interior edge of `h`: 3/8 (a + b) + 1/8 (c + d).
glm::dvec3 interior_edge_point(const HalfedgeMesh& before, HalfedgeId h) {
  const HalfedgeId t = before.twin(h);
  return loop_rules::interior_edge(before.position(before.vertex(h)), before.position(before.vertex(t)),
                                   before.position(before.vertex(before.next(before.next(h)))),
                                   before.position(before.vertex(before.next(before.next(t)))));
}

std::vector<std::string> edge_messages(const HalfedgeMesh& before, const HalfedgeMesh& yours, double tolerance) {
  Tally across, without_d, other;
  const uint32_t old_capacity = before.vertex_capacity();
  for (VertexId w : yours.vertices()) {
    if (w.index < old_capacity) continue;
    // The edges of the original mesh between two of w's original neighbours: w was made on one of them, and flips that
    // went wrong may have joined it to the ends of others. Where the course's rule puts the new vertex of any of them
    // (a boundary edge's midpoint, an interior edge's 3/8 and 1/8), w is right.
    const std::vector<VertexId> old_neighbours = original_neighbours(before, yours, w);
    const glm::dvec3& q = yours.position(w);
    std::optional<std::pair<EdgePlace, std::string>> first;
    bool placed_right = false;
    for (size_t i = 0; i < old_neighbours.size() && !placed_right; ++i) {
      for (size_t j = i + 1; j < old_neighbours.size() && !placed_right; ++j) {
        HalfedgeId inside = halfedge_between(before, old_neighbours[i], old_neighbours[j]);
        if (!inside.valid()) continue;
        HalfedgeId outside = before.twin(inside);
        if (before.face(inside).is_boundary()) std::swap(inside, outside);
        if (before.face(inside).is_boundary()) continue;
        if (!before.face(outside).is_boundary()) {  // an interior edge: w may have been made there, by its rule
          placed_right = close(q, interior_edge_point(before, inside), tolerance);
          continue;
        }
        const EdgePlace place = edge_place(before, inside, outside, q, tolerance);
        placed_right = place == EdgePlace::Midpoint;
        if (!first) {
          first.emplace(
              place, tr_format("{vertex} on the boundary edge {edge}",
                               {{"vertex", format_id(w)},
                                {"edge", format_id(before.vertex(inside)) + "-" + format_id(before.vertex(outside))}}));
        }
      }
    }
    if (placed_right || !first) continue;
    switch (first->first) {
      case EdgePlace::Across: across.add(first->second); break;
      case EdgePlace::WithoutD: without_d.add(first->second); break;
      case EdgePlace::Other:
        other.add(tr_format("{example} at {position}", {{"example", first->second}, {"position", format_position(q)}}));
        break;
      case EdgePlace::Midpoint: break;
    }
  }
  const std::string rule = tr("a boundary edge's new vertex goes at its midpoint, (a + b) / 2 (extra credit)");
  std::vector<std::string> out;
  if (across.count > 0) {
    out.push_back(
        tr_format("{count} of your new vertices, e.g. {example}, are at the interior rule 3/8 (a + b) + 1/8 "
                  "(c + d) with d read across the boundary (h.twin.next.next walks the boundary loop, not a "
                  "triangle); {rule}",
                  {{"count", std::to_string(across.count)}, {"example", across.example}, {"rule", rule}}));
  }
  if (without_d.count > 0) {
    const MessageParts parts = {
        {"count", std::to_string(without_d.count)}, {"example", without_d.example}, {"rule", rule}};
    out.push_back(
        tr_format("{count} of your new vertices, e.g. {example}, are at 3/8 (a + b) + 1/8 c, the interior "
                  "rule with d left out; {rule}",
                  parts));
  }
  if (other.count > 0) {
    out.push_back(
        tr_format("{count} of your new vertices on boundary edges are not at the midpoint, e.g. {example}: "
                  "{rule}",
                  {{"count", std::to_string(other.count)}, {"example", other.example}, {"rule", rule}}));
  }
  return out;
}

}  // namespace

std::vector<std::string> diagnose_loop_boundary(const HalfedgeMesh& before, const HalfedgeMesh& yours,
                                                double tolerance) {
  std::vector<std::string> out = vertex_messages(before, yours, tolerance);
  for (std::string& m : edge_messages(before, yours, tolerance)) out.push_back(std::move(m));
  return out;
}

}  // namespace meshedit
