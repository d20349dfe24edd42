// Wrong flips in Loop subdivision, counted from connectivity (see loop_flip_diagnosis.h).
#include "exercise/internal/loop_flip_diagnosis.h"

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/loop_subdivision.h"
#include "core/translation.h"

namespace meshedit {
namespace {

// An edge as the pair of its ends' ids, the smaller first.
using EdgeKey = std::pair<uint32_t, uint32_t>;

EdgeKey key_of(VertexId a, VertexId b) {
  return a.index < b.index ? EdgeKey{a.index, b.index} : EdgeKey{b.index, a.index};
}

std::set<EdgeKey> edge_keys(const HalfedgeMesh& mesh) {
  std::set<EdgeKey> keys;
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    if (mesh.alive(h) && mesh.alive(mesh.twin(h))) keys.insert(key_of(mesh.vertex(h), mesh.vertex(mesh.twin(h))));
  }
  return keys;
}

// The core's mesh after splitting every original edge (phases 1 and 2); nullopt when the core refuses `before`.
std::optional<HalfedgeMesh> reference_after_splits(const HalfedgeMesh& before) {
  OpResult<LoopState> loop = loop_compute_positions(before, LoopWeights::Course);
  if (!loop.ok()) return std::nullopt;
  HalfedgeMesh split = before;
  loop_split_edges(split, loop.value);
  return split;
}

struct Tally {
  size_t count = 0;
  EdgeId example;
  void add(EdgeId e) {
    if (count++ == 0) example = e;
  }
};

enum Ends { kOldAndNew, kBothOld, kBothNew, kEndsKinds };

struct FlipTallies {
  size_t reference_flips = 0;     // edges of the split mesh the finished reference does not have
  size_t right = 0;               // yours, in the finished reference and not in the split mesh
  Tally unflipped;                // yours, in the split mesh and not in the finished reference
  size_t unflipped_from_new = 0;  // of those, how many have their halfedge (e.halfedge) leaving the new vertex
  Tally wrong[kEndsKinds];        // yours, in neither, by the age of their ends
  size_t wrong_total() const { return wrong[kOldAndNew].count + wrong[kBothOld].count + wrong[kBothNew].count; }
};

FlipTallies count_flips(const HalfedgeMesh& before, const HalfedgeMesh& yours, const HalfedgeMesh& split,
                        const HalfedgeMesh& reference, const MeshComparison& c) {
  const std::set<EdgeKey> split_edges = edge_keys(split), finished_edges = edge_keys(reference);
  FlipTallies t;
  for (const EdgeKey& k : split_edges) t.reference_flips += finished_edges.contains(k) ? 0 : 1;
  const uint32_t old_capacity = before.vertex_capacity();
  for (EdgeId e : yours.edges()) {
    const HalfedgeId h = yours.halfedge(e);
    if (!yours.alive(h) || !yours.alive(yours.twin(h))) continue;
    const uint32_t x = yours.vertex(h).index, y = yours.vertex(yours.twin(h)).index;
    if (x >= c.vertex_map.size() || y >= c.vertex_map.size()) continue;
    const VertexId a = c.vertex_map[x], b = c.vertex_map[y];
    if (!a.valid() || !b.valid()) continue;
    const EdgeKey k = key_of(a, b);
    const bool in_split = split_edges.contains(k), in_finished = finished_edges.contains(k);
    if (in_finished && !in_split) ++t.right;
    if (in_split && !in_finished) {
      t.unflipped.add(e);
      t.unflipped_from_new += a.index >= old_capacity ? 1 : 0;
    }
    if (in_split || in_finished) continue;
    const bool a_old = a.index < old_capacity, b_old = b.index < old_capacity;
    t.wrong[a_old && b_old ? kBothOld : (!a_old && !b_old ? kBothNew : kOldAndNew)].add(e);
  }
  return t;
}

std::string ends_of(const HalfedgeMesh& mesh, EdgeId e) {
  const HalfedgeId h = mesh.halfedge(e);
  return format_id(e) + " (" + format_id(mesh.vertex(h)) + " " + format_id(mesh.vertex(mesh.twin(h))) + ")";
}

// "your upsample flipped none of the 4 new edges the reference flips" / "2 of the 4".
std::string flipped_of(const FlipTallies& t) {
  const MessageParts parts = {{"count", std::to_string(t.right)}, {"total", std::to_string(t.reference_flips)}};
  return t.right == 0 ? tr_format("your upsample flipped none of the {total} new edges the reference flips", parts)
                      : tr_format("your upsample flipped {count} of the {total} new edges the reference flips", parts);
}

// The old/new test made one way only, with what the edges left say about it: when all of them have e.halfedge
// leaving the same kind of vertex, a test of one order never flips any of them.
std::string one_way_cause(const FlipTallies& t) {
  const size_t left = t.unflipped.count;
  if (left > 1 && t.unflipped_from_new == left) {
    return tr(
        "the old/new test accepts one order only (a old and b new, but not a new and b old: flip when "
        "(is_new[a.id] == true) ~= (is_new[b.id] == true)): every edge left has its halfedge leaving the new "
        "vertex, so a test of one order never flips them");
  }
  if (left > 1 && t.unflipped_from_new == 0) {
    return tr(
        "the old/new test accepts one order only (a old and b new, but not a new and b old: flip when "
        "(is_new[a.id] == true) ~= (is_new[b.id] == true)): every edge left has its halfedge leaving the "
        "original vertex, so a test of one order never flips them");
  }
  return tr(
      "the old/new test accepts one order only (a old and b new, but not a new and b old: flip when "
      "(is_new[a.id] == true) ~= (is_new[b.id] == true))");
}

// How many of the reference's flips yours made, the new edges left unflipped, and their causes, likely first.
std::string unflipped_message(const FlipTallies& t, const HalfedgeMesh& yours) {
  const std::string marks =
      tr("the marks never match (a table keyed by the handle, new_edge[e] = true or is_new[m] = true, or by anything "
         "but the element's id, finds nothing when another handle reads it back: key them by e.id and m.id)");
  const std::string flags =
      tr("the flags were set on the wrong edges (the halves of the split edge instead of the edges from the new vertex "
         "to the opposite corners)");
  const std::string one_way = one_way_cause(t);
  const bool wrong = t.wrong_total() > 0, none = t.right == 0;
  const MessageParts parts = {{"flipped", flipped_of(t)},
                              {"count", std::to_string(t.unflipped.count)},
                              {"example", ends_of(yours, t.unflipped.example)},
                              {"first", wrong  ? flags
                                        : none ? marks
                                               : one_way},
                              {"second", wrong  ? marks
                                         : none ? one_way
                                                : marks},
                              {"third", wrong ? one_way : flags}};
  return tr_format(
      "{flipped}: {count} of your edges still join an original and a new vertex across an old face, "
      "e.g. {example}, where the reference has none (every new edge that joins an old and a new vertex "
      "must be flipped, once). The usual causes, most likely first: {first}; {second}; or {third}",
      parts);
}

// What an edge in neither the split mesh nor the finished reference says, by the age of its ends: the message, with
// the number of such edges ({count}) and the first of them ({example}).
struct WrongFlipWords {
  Ends ends;
  const char* message;
};
constexpr WrongFlipWords kWrongFlipWords[] = {
    {kBothOld,
     "{count} of your edges join two original vertices, e.g. {example}: a new edge whose ends were both new was "
     "flipped; flip only new edges with one old and one new end (check both ends)"},
    {kBothNew,
     "{count} of your edges join two new vertices where the reference has none, e.g. {example}: an edge that was not "
     "new (a half of a split edge) was flipped; flag only the edges from the new vertex m to the corners opposite the "
     "split edge (the far ends other than the split edge's own two)"},
    {kOldAndNew,
     "{count} of your edges join an original and a new vertex where neither the splits nor the reference's flips make "
     "one, e.g. {example}: an edge that had to stay was flipped (a half of a split edge, or a new edge between two new "
     "vertices)"},
};

// Edges in neither the split mesh nor the finished reference, by the age of their ends.
std::vector<std::string> wrong_flip_messages(const FlipTallies& t, const HalfedgeMesh& yours) {
  std::vector<std::string> out;
  for (const WrongFlipWords& words : kWrongFlipWords) {
    const Tally& tally = t.wrong[words.ends];
    if (tally.count == 0) continue;
    out.push_back(
        tr_format(words.message, {{"count", std::to_string(tally.count)}, {"example", ends_of(yours, tally.example)}}));
  }
  return out;
}

}  // namespace

std::vector<std::string> diagnose_loop_flips(const HalfedgeMesh& before, const HalfedgeMesh& yours,
                                             const HalfedgeMesh& reference, const MeshComparison& comparison) {
  if (!comparison.unmatched_vertices.empty() || !comparison.unmatched_reference.empty() ||
      comparison.extra_edges.empty()) {
    return {};
  }
  const std::optional<HalfedgeMesh> split = reference_after_splits(before);
  if (!split) return {};
  const FlipTallies t = count_flips(before, yours, *split, reference, comparison);
  std::vector<std::string> out = wrong_flip_messages(t, yours);
  if (t.unflipped.count > 0) {
    out.push_back(unflipped_message(t, yours));
  } else if (t.wrong_total() > 0) {
    out.push_back(
        tr_format("{flipped}, and {count} of your edges are ones neither the splits nor the reference's "
                  "flips make (each from a flip of an edge that had to stay)",
                  {{"flipped", flipped_of(t)}, {"count", std::to_string(t.wrong_total())}}));
  }
  return out;
}

}  // namespace meshedit
