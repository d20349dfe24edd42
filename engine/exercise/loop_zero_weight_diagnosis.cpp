// Loop weights that integer division made 0, read from positions (see loop_zero_weight_diagnosis.h).
#include "exercise/internal/loop_zero_weight_diagnosis.h"

#include <cstdint>

#include <glm/geometric.hpp>

#include "core/loop_rules.h"
#include "core/translation.h"
#include "core/value_format.h"
#include "core/vertex_ring.h"
#include "exercise/internal/loop_diagnosis_support.h"

namespace meshedit {
namespace {

using namespace loop_diagnosis;

// A rule with some of its weights 0: the message naming them and where they put a vertex (a template with the
// number of such vertices, {count}, and the first of them, {example}), and who is there.
struct ZeroedRule {
  const char* message;  // "your edge weights 3/8 and 1/8 are 0 (in Lua ...): {count} of your new vertices, ..."
  bool at_origin;       // every weight of the rule is 0: it puts the vertex at (0, 0, 0)
  size_t count = 0;
  std::string example;
  void add(const std::string& text) {
    if (count++ == 0) example = text;
  }
};

// "your edge weights 3/8 and 1/8 are 0 (in Lua ...): 6 of your new vertices, e.g. ..., are at ... instead of ...".
void tell(const ZeroedRule& z, ZeroLoopWeights& out) {
  if (z.count == 0) return;
  out.messages.push_back(tr_format(z.message, {{"count", std::to_string(z.count)}, {"example", z.example}}));
  out.origin_told = out.origin_told || z.at_origin;
}

// Which zeroed rule q fits: the one with every weight zeroed first (nullptr: none).
ZeroedRule* fit(ZeroedRule* rules, const glm::dvec3* positions, size_t n, const glm::dvec3& q, double tolerance) {
  for (size_t i = 0; i < n; ++i) {
    if (close(q, positions[i], tolerance)) return &rules[i];
  }
  return nullptr;
}

// New vertices of interior and boundary edges; returns whether step 5 visibly ran (a new vertex of an interior edge
// of `before` is at none of its edges' midpoints).
bool edge_messages(const HalfedgeMesh& before, const HalfedgeMesh& yours, double tolerance, ZeroLoopWeights& out) {
  ZeroedRule interior[] = {
      {"your edge weights 3/8 and 1/8 are 0 (in Lua 3 // 8 and 1 // 8 are 0, integer divisions: write 3 / 8 and "
       "1 / 8): {count} of your new vertices, e.g. {example}, are at (0, 0, 0) instead of 3/8 (a + b) + 1/8 (c + d)",
       true},
      {"your edge weight 3/8 is 0 (in Lua 3 // 8 is 0, an integer division: write 3 / 8): {count} of your new "
       "vertices, e.g. {example}, are at 1/8 (c + d) instead of 3/8 (a + b) + 1/8 (c + d)",
       false},
      {"your edge weight 1/8 is 0 (in Lua 1 // 8 is 0, an integer division: write 1 / 8): {count} of your new "
       "vertices, e.g. {example}, are at 3/8 (a + b) instead of 3/8 (a + b) + 1/8 (c + d)",
       false}};
  ZeroedRule boundary[] = {
      {"your boundary edge weight 1/2 is 0 (in Lua 1 // 2 is 0, an integer division: write 1 / 2): {count} of your "
       "new vertices on boundary edges, e.g. {example}, are at (0, 0, 0) instead of the midpoint (a + b) / 2",
       true}};
  bool moved = false;
  const uint32_t old_capacity = before.vertex_capacity();
  for (VertexId w : yours.vertices()) {
    if (w.index < old_capacity) continue;
    const std::vector<VertexId> old = original_neighbours(before, yours, w);
    const glm::dvec3& q = yours.position(w);
    bool at_midpoint = false, interior_edge = false, told = false;
    for (size_t i = 0; i < old.size(); ++i) {
      for (size_t j = i + 1; j < old.size() && !told; ++j) {
        const HalfedgeId h = halfedge_between(before, old[i], old[j]);
        if (!h.valid()) continue;
        const glm::dvec3 a = before.position(old[i]), b = before.position(old[j]);
        at_midpoint = at_midpoint || close(q, 0.5 * (a + b), tolerance);
        const std::string where =
            tr_format("{vertex} on the edge {edge}",
                      {{"vertex", format_id(w)}, {"edge", format_id(old[i]) + "-" + format_id(old[j])}});
        if (before.face(h).is_boundary() || before.face(before.twin(h)).is_boundary()) {
          const glm::dvec3 zeroed[] = {glm::dvec3(0.0)};
          if (close(q, 0.5 * (a + b), tolerance)) continue;
          if (ZeroedRule* z = fit(boundary, zeroed, 1, q, tolerance)) {
            z->add(where);
            told = true;
          }
          continue;
        }
        interior_edge = true;
        const glm::dvec3 c = before.position(before.vertex(before.next(before.next(h))));
        const glm::dvec3 d = before.position(before.vertex(before.next(before.next(before.twin(h)))));
        if (close(q, loop_rules::interior_edge(a, b, c, d), tolerance)) continue;
        const glm::dvec3 zeroed[] = {glm::dvec3(0.0), 0.125 * (c + d), 0.375 * (a + b)};
        if (ZeroedRule* z = fit(interior, zeroed, 3, q, tolerance)) {
          z->add(where);
          told = true;
        }
      }
    }
    moved = moved || (interior_edge && !at_midpoint);
  }
  for (const ZeroedRule& z : interior) tell(z, out);
  tell(boundary[0], out);
  return moved;
}

void boundary_vertex_messages(const HalfedgeMesh& before, const HalfedgeMesh& yours, double tolerance,
                              ZeroLoopWeights& out) {
  ZeroedRule rules[] = {
      {"your boundary vertex weights 3/4 and 1/8 are 0 (in Lua 3 // 4 and 1 // 8 are 0, integer divisions: write "
       "3 / 4 and 1 / 8): {count} of your boundary vertices, e.g. {example}, are at (0, 0, 0) instead of 3/4 p + "
       "1/8 (a + b)",
       true},
      {"your boundary vertex weight 3/4 is 0 (in Lua 3 // 4 is 0, an integer division: write 3 / 4): {count} of your "
       "boundary vertices, e.g. {example}, are at 1/8 (a + b) instead of 3/4 p + 1/8 (a + b)",
       false},
      {"your boundary vertex weight 1/8 is 0 (in Lua 1 // 8 is 0, an integer division: write 1 / 8): {count} of your "
       "boundary vertices, e.g. {example}, are at 3/4 p instead of 3/4 p + 1/8 (a + b)",
       false}};
  for (VertexId v : before.vertices()) {
    if (!yours.alive(v)) continue;
    const VertexRing ring = vertex_ring(before, v);
    if (!ring.closed || ring.rim_count != 2) continue;
    const glm::dvec3 p = before.position(v), rim = before.position(ring.rim[0]) + before.position(ring.rim[1]);
    const glm::dvec3& q = yours.position(v);
    if (close(q, 0.75 * p + 0.125 * rim, tolerance)) continue;
    const glm::dvec3 zeroed[] = {glm::dvec3(0.0), 0.125 * rim, 0.75 * p};
    if (ZeroedRule* z = fit(rules, zeroed, 3, q, tolerance)) z->add(format_id(v));
  }
  for (const ZeroedRule& z : rules) tell(z, out);
}

// Interior original vertices left at p, by branch of u: [0] degree 3 (u = 3/16), [1] the others (u = 3 / (8 n)).
void interior_vertex_message(const HalfedgeMesh& before, const HalfedgeMesh& yours, double tolerance,
                             ZeroLoopWeights& out) {
  size_t total[2] = {}, stayed[2] = {};
  for (VertexId v : before.vertices()) {
    if (!yours.alive(v)) continue;
    const VertexRing ring = vertex_ring(before, v);
    if (!ring.closed || ring.rim_count != 0 || ring.valence == 0) continue;
    const glm::dvec3& p = before.position(v);
    const double u = course_u(ring.valence);
    const glm::dvec3 course = loop_rules::interior_vertex(p, ring.neighbour_sum, ring.valence, u);
    if (close(course, p, tolerance)) continue;  // the course's rule leaves it in place: nothing to tell
    const size_t branch = ring.valence == 3 ? 0 : 1;
    ++total[branch];
    if (close(yours.position(v), p, tolerance)) ++stayed[branch];
  }
  const bool one_weight = (stayed[0] == 0 || stayed[0] == total[0]) && (stayed[1] == 0 || stayed[1] == total[1]);
  if (stayed[0] + stayed[1] == 0 || !one_weight) return;
  const bool both = stayed[0] > 0 && stayed[1] > 0;
  const MessageParts parts = {{"count", std::to_string(stayed[0] + stayed[1])},
                              {"total", std::to_string(total[0] + total[1])}};
  if (both) {
    out.messages.push_back(tr_format(
        "your weight u is 0 (in Lua 3 // 16 and 3 // (8 * n) are 0, integer divisions: write 3 / 16 and 3 / (8 * n)): "
        "{count} of the {total} original vertices kept their old positions while your new vertices moved; an "
        "original vertex moves to (1 - n u) p + u (sum of the neighbours), u = 3/16 for degree 3, else 3 / (8 n) (if "
        "your u is not 0, step 5 must move the original vertices too)",
        parts));
  } else if (stayed[0] > 0) {
    out.messages.push_back(tr_format(
        "your weight u is 0 for degree 3 (in Lua 3 // 16 is 0, an integer division: write 3 / 16): {count} of the "
        "{total} original vertices kept their old positions while your new vertices moved; an original vertex moves "
        "to (1 - n u) p + u (sum of the neighbours), u = 3/16 for degree 3, else 3 / (8 n) (if your u is not 0, step "
        "5 must move the original vertices too)",
        parts));
  } else {
    out.messages.push_back(tr_format(
        "your weight u is 0 for degrees other than 3 (in Lua 3 // (8 * n) is 0, an integer division: write "
        "3 / (8 * n)): {count} of the {total} original vertices kept their old positions while your new vertices "
        "moved; an original vertex moves to (1 - n u) p + u (sum of the neighbours), u = 3/16 for degree 3, else "
        "3 / (8 n) (if your u is not 0, step 5 must move the original vertices too)",
        parts));
  }
  out.originals_unmoved = true;
}

}  // namespace

ZeroLoopWeights diagnose_zero_loop_weights(const HalfedgeMesh& before, const HalfedgeMesh& yours, double tolerance) {
  ZeroLoopWeights out;
  ZeroLoopWeights edges;
  const bool step_5_ran = edge_messages(before, yours, tolerance, edges);
  if (step_5_ran) interior_vertex_message(before, yours, tolerance, out);
  boundary_vertex_messages(before, yours, tolerance, out);
  for (std::string& m : edges.messages) out.messages.push_back(std::move(m));
  out.origin_told = out.origin_told || edges.origin_told;
  return out;
}

}  // namespace meshedit
