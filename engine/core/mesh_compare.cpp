// Mesh comparison, exact and up to renumbering (see mesh_compare.h for the contract).
//
// Up to renumbering, in four passes: pair vertices by position through a hash grid of the reference's
// vertices (cells as large as the tolerance, so a match lies in one of the 27 cells around a point), then
// translate your faces, boundary loops and edges into reference vertex ids and match them as multisets
// of canonical keys (a cycle rotated to start at its smallest id keeps its orientation; an edge is its
// sorted pair). Messages past the cap are counted but never formatted: nearest-vertex searches for
// messages are brute force and run at most max_differences times.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   shared                               Collector (counts all, formats under the cap), compare_counts, same_position
//   exact                                compare_pointer, compare_element: pointer for pointer
//   up to renumbering: vertices          VertexGrid (the hash grid), nearest, no_match (the message)
//   up to renumbering: cycles and edges  read_cycle, match_cycles and their reports, compare_cycles, compare_edges
//   public functions                     mesh_tolerance, points_tolerance, summary, compare_meshes_exact,
//                                        compare_meshes
#include "core/mesh_compare.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/finite.h"
#include "core/translation.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

// ---- shared ----------------------------------------------------------------------------------------

// Counts every difference, formats only those under the cap.
class Collector {
 public:
  Collector(MeshComparison& out, size_t cap) : out_(out), cap_(cap) {}
  template <class MakeMessage>
  void add(MakeMessage&& make_message) {
    ++out_.total_differences;
    if (out_.differences.size() < cap_) out_.differences.push_back(make_message());
  }

 private:
  MeshComparison& out_;
  size_t cap_;
};

void compare_counts(const HalfedgeMesh& yours, const HalfedgeMesh& reference, Collector& out) {
  struct Count {
    size_t yours, reference;
    const char* one;   // the template when the reference has exactly one
    const char* many;  // otherwise
  };
  const Count counts[] = {
      {yours.num_vertices(), reference.num_vertices(), "the reference has {count} vertex, yours {yours}",
       "the reference has {count} vertices, yours {yours}"},
      {yours.num_edges(), reference.num_edges(), "the reference has {count} edge, yours {yours}",
       "the reference has {count} edges, yours {yours}"},
      {yours.num_faces(), reference.num_faces(), "the reference has {count} face, yours {yours}",
       "the reference has {count} faces, yours {yours}"},
      {yours.num_halfedges(), reference.num_halfedges(), "the reference has {count} halfedge, yours {yours}",
       "the reference has {count} halfedges, yours {yours}"},
      {yours.num_boundaries(), reference.num_boundaries(), "the reference has {count} boundary loop, yours {yours}",
       "the reference has {count} boundary loops, yours {yours}"},
  };
  for (const Count& c : counts) {
    if (c.yours == c.reference) continue;
    out.add([&] {
      return tr_format(c.reference == 1 ? c.one : c.many,
                       {{"count", std::to_string(c.reference)}, {"yours", std::to_string(c.yours)}});
    });
  }
}

bool same_position(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
  if (std::memcmp(&a, &b, sizeof(a)) == 0) return true;
  return glm::distance(a, b) <= tolerance;
}

// ---- exact -------------------------------------------------------------------------------------------

void compare_pointer(Collector& out, ElementRef owner, const char* field, ElementRef yours, ElementRef reference) {
  if (yours == reference) return;
  out.add([&] {
    return tr_format("{element}.{field} is {yours} in yours, {reference} in the reference",
                     {{"element", format_id(owner)},
                      {"field", field},
                      {"yours", format_id(yours)},
                      {"reference", format_id(reference)}});
  });
}

void compare_element(const HalfedgeMesh& y, const HalfedgeMesh& r, ElementRef e, double tolerance, Collector& out) {
  switch (e.kind) {
    case ElementKind::Halfedge: {
      const HalfedgeId h(e.index);
      compare_pointer(out, e, "next", y.next(h), r.next(h));
      compare_pointer(out, e, "twin", y.twin(h), r.twin(h));
      compare_pointer(out, e, "vertex", y.vertex(h), r.vertex(h));
      compare_pointer(out, e, "edge", y.edge(h), r.edge(h));
      compare_pointer(out, e, "face", y.face(h), r.face(h));
      break;
    }
    case ElementKind::Vertex: {
      const VertexId v(e.index);
      compare_pointer(out, e, "halfedge", y.halfedge(v), r.halfedge(v));
      if (!same_position(y.position(v), r.position(v), tolerance)) {
        out.add([&] {
          return tr_format("{element}.{field} is {yours} in yours, {reference} in the reference",
                           {{"element", format_id(e)},
                            {"field", "position"},
                            {"yours", format_position(y.position(v))},
                            {"reference", format_position(r.position(v))}});
        });
      }
      break;
    }
    case ElementKind::Edge:
      compare_pointer(out, e, "halfedge", y.halfedge(EdgeId(e.index)), r.halfedge(EdgeId(e.index)));
      break;
    case ElementKind::Face:
    case ElementKind::Boundary:
      compare_pointer(out, e, "halfedge", y.halfedge(e.face_id()), r.halfedge(e.face_id()));
      break;
  }
}

// ---- up to renumbering: vertices -----------------------------------------------------------------

struct Cell {
  double x, y, z;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct CellHash {
  size_t operator()(const Cell& c) const noexcept {
    const std::hash<double> h;
    size_t s = h(c.x);
    s ^= h(c.y) + 0x9e3779b97f4a7c15ull + (s << 6) + (s >> 2);
    s ^= h(c.z) + 0x9e3779b97f4a7c15ull + (s << 6) + (s >> 2);
    return s;
  }
};

class VertexGrid {
 public:
  VertexGrid(const HalfedgeMesh& mesh, double tolerance)
      : mesh_(mesh), tolerance_(tolerance), cell_(tolerance > 0.0 ? tolerance : 1.0) {
    for (VertexId v : mesh.vertices()) {
      if (finite(mesh.position(v))) cells_[cell_of(mesh.position(v))].push_back(v.index);
    }
  }
  // Calls fn(reference vertex, distance) for every vertex within the tolerance of p (p finite).
  template <class Fn>
  void for_each_near(const glm::dvec3& p, Fn&& fn) const {
    const Cell c = cell_of(p);
    std::vector<uint32_t> seen;  // a cell can repeat when coordinates are too large for +-1 to change them
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(Cell{c.x + dx + 0.0, c.y + dy + 0.0, c.z + dz + 0.0});
          if (it == cells_.end()) continue;
          for (uint32_t v : it->second) {
            const double d = glm::distance(p, mesh_.position(VertexId(v)));
            if (d <= tolerance_ && std::find(seen.begin(), seen.end(), v) == seen.end()) {
              seen.push_back(v);
              fn(VertexId(v), d);
            }
          }
        }
      }
    }
  }

 private:
  Cell cell_of(const glm::dvec3& p) const {
    // + 0.0 turns -0 into +0, so both land in one cell.
    return Cell{std::floor(p.x / cell_) + 0.0, std::floor(p.y / cell_) + 0.0, std::floor(p.z / cell_) + 0.0};
  }
  const HalfedgeMesh& mesh_;
  double tolerance_;
  double cell_;
  std::unordered_map<Cell, std::vector<uint32_t>, CellHash> cells_;
};

// The live vertex of `mesh` nearest to p (brute force; only for messages), or invalid if there is none.
VertexId nearest(const HalfedgeMesh& mesh, const glm::dvec3& p, double& distance) {
  VertexId best;
  distance = std::numeric_limits<double>::infinity();
  for (VertexId v : mesh.vertices()) {
    const double d = glm::distance(p, mesh.position(v));
    if (finite(mesh.position(v)) && d < distance) {
      best = v;
      distance = d;
    }
  }
  return best;
}

// The templates of no_match for a vertex of one mesh, told in the other.
struct NoMatchTexts {
  const char* not_finite;
  const char* other_empty;      // the other mesh has no vertices
  const char* nearest;          // the other mesh's nearest vertex
  const char* nearest_matched;  // ... which is already matched to another of this mesh
};
constexpr NoMatchTexts kYourVertex{
    "your vertex {vertex} at {position} has a position that is not finite; it matches nothing",
    "your vertex {vertex} at {position} has no match in the reference (which has no vertices)",
    "your vertex {vertex} at {position} has no match in the reference; the nearest is reference {nearest} at "
    "{nearest_position}, {distance} away",
    "your vertex {vertex} at {position} has no match in the reference; the nearest is reference {nearest} at "
    "{nearest_position}, {distance} away (already matched to your {partner})"};
constexpr NoMatchTexts kReferenceVertex{
    "reference vertex {vertex} at {position} has a position that is not finite; it matches nothing",
    "reference vertex {vertex} at {position} has no match in yours (which has no vertices)",
    "reference vertex {vertex} at {position} has no match in yours; the nearest is your {nearest} at "
    "{nearest_position}, {distance} away",
    "reference vertex {vertex} at {position} has no match in yours; the nearest is your {nearest} at "
    "{nearest_position}, {distance} away (already matched to reference {partner})"};

std::string no_match(const HalfedgeMesh& from, VertexId v, const HalfedgeMesh& other,
                     const std::vector<VertexId>& other_partner, const NoMatchTexts& texts) {
  const glm::dvec3& p = from.position(v);
  MessageParts parts = {{"vertex", format_id(v)}, {"position", format_position(p)}};
  if (!finite(p)) return tr_format(texts.not_finite, parts);
  double distance = 0.0;
  const VertexId n = nearest(other, p, distance);
  if (!n.valid()) return tr_format(texts.other_empty, parts);
  parts.insert(parts.end(), {{"nearest", format_id(n)},
                             {"nearest_position", format_position(other.position(n))},
                             {"distance", format_number(distance)}});
  if (n.index < other_partner.size() && other_partner[n.index].valid()) {
    parts.emplace_back("partner", format_id(other_partner[n.index]));
    return tr_format(texts.nearest_matched, parts);
  }
  return tr_format(texts.nearest, parts);
}

// ---- up to renumbering: cycles and edges ---------------------------------------------------------

using Key = std::vector<uint32_t>;

// Rotated so the smallest id comes first; the order (orientation) is kept.
Key canonical(Key key) {
  if (!key.empty()) std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
  return key;
}

Key reversed(const Key& key) { return canonical(Key(key.rbegin(), key.rend())); }

std::string list(const Key& vertices) {
  std::string s;
  for (uint32_t v : vertices) s += (s.empty() ? "" : " ") + format_id(VertexId(v));
  return s;
}

// A face or loop as your/reference vertex ids, in walking order from its halfedge.
struct Cycle {
  FaceId face;
  Key vertices;    // in the mesh's own ids
  Key translated;  // in the other mesh's ids (yours -> reference); empty if a corner has no match
  bool broken = false;
};

Cycle read_cycle(const HalfedgeMesh& mesh, FaceId f, const std::vector<VertexId>& map) {
  Cycle c{f, {}, {}, false};
  const bool closed = mesh.for_each_face_halfedge(f, [&](HalfedgeId h) {
    const VertexId v = mesh.vertex(h);
    if (!mesh.alive(v)) c.broken = true;
    c.vertices.push_back(v.index);
  });
  if (!closed || c.broken || c.vertices.size() < 3) {
    c.broken = true;
    return c;
  }
  for (uint32_t v : c.vertices) {
    if (v >= map.size() || !map[v].valid()) {
      c.translated.clear();
      return c;
    }
    c.translated.push_back(map[v].index);
  }
  return c;
}

// Whose the other mesh's names are in corners() and edge_ends(): "reference" or "your".
enum class Other : uint8_t { Reference, Yours };

// "(v0 v4 v7)", plus the other mesh's names when they differ: "(v0 v4 v7; your v0 v5 v9)".
std::string named_corners(const std::string& own, const Key& translated, bool differ, Other other) {
  if (translated.empty() || !differ) return tr_format("({corners})", {{"corners", own}});
  const MessageParts parts = {{"corners", own}, {"other", list(translated)}};
  return other == Other::Reference ? tr_format("({corners}; reference {other})", parts)
                                   : tr_format("({corners}; your {other})", parts);
}

std::string corners(const Cycle& c, Other other) {
  return named_corners(list(c.vertices), c.translated, c.translated != c.vertices, other);
}

// The messages about one kind of cycle: {face} is its id, {corners} its corners().
struct CycleTexts {
  const char* your_broken;
  const char* your_reversed;  // {reference_face} {reference_corners}: the reference's cycle it matched reversed
  const char* your_extra;
  const char* reference_broken;
  const char* reference_missing;
  const char* skipped;  // {mine} of yours and {theirs} of the reference's were not compared
};
constexpr CycleTexts kFaceTexts{
    "your face {face} cannot be walked: its next-cycle does not close, has fewer than 3 halfedges, or reaches a dead "
    "element",
    "your face {face} {corners} has the opposite orientation of reference face {reference_face} {reference_corners}",
    "your face {face} {corners} is not in the reference",
    "reference face {face} cannot be walked",
    "reference face {face} {corners} is missing from yours",
    "{mine} of your faces and {theirs} of the reference's touch a vertex without a match and were not compared"};
constexpr CycleTexts kBoundaryTexts{
    "your boundary loop {face} cannot be walked: its next-cycle does not close, has fewer than 3 halfedges, or "
    "reaches a dead element",
    "your boundary loop {face} {corners} has the opposite orientation of reference boundary loop {reference_face} "
    "{reference_corners}",
    "your boundary loop {face} {corners} is not in the reference",
    "reference boundary loop {face} cannot be walked",
    "reference boundary loop {face} {corners} is missing from yours",
    "{mine} of your boundary loops and {theirs} of the reference's touch a vertex without a match and were not "
    "compared"};

struct CycleKinds {
  const CycleTexts* texts;
  std::vector<FaceId>* extra;
  std::vector<FaceId>* missing;
  std::vector<FaceId>* reversed;  // null for boundary loops: a loop runs the way its faces say
};

// How a cycle matched one of the other mesh: not at all, as it is, or with the opposite orientation.
enum class Match : uint8_t { None, Same, Reversed };

struct CycleMatching {
  std::vector<Match> yours;     // per cycle of yours
  std::vector<size_t> partner;  // per cycle of yours: the reference cycle it matched
  std::vector<Match> theirs;    // per reference cycle
};

// Yours matched to the reference's: a cycle takes one with the same canonical key, then (when `try_reversed`) one
// with the reversed key. Each reference cycle is used at most once, the lowest id first.
CycleMatching match_cycles(const std::vector<Cycle>& mine, const std::vector<Cycle>& theirs, bool try_reversed) {
  std::map<Key, std::vector<size_t>> by_key;
  for (size_t i = theirs.size(); i-- > 0;) {  // reversed so pop_back hands out the lowest id first
    if (!theirs[i].broken && !theirs[i].translated.empty()) {
      by_key[canonical(theirs[i].vertices)].push_back(i);
    }
  }
  CycleMatching m{std::vector<Match>(mine.size(), Match::None), std::vector<size_t>(mine.size(), 0),
                  std::vector<Match>(theirs.size(), Match::None)};
  const auto take = [&](const Key& key, size_t i, Match how) {
    auto it = by_key.find(key);
    if (it == by_key.end() || it->second.empty()) return;
    m.partner[i] = it->second.back();
    it->second.pop_back();
    m.theirs[m.partner[i]] = how;
    m.yours[i] = how;
  };
  const auto comparable = [&](size_t i) { return !mine[i].broken && !mine[i].translated.empty(); };
  for (size_t i = 0; i < mine.size(); ++i) {
    if (comparable(i)) take(canonical(mine[i].translated), i, Match::Same);
  }
  if (try_reversed) {
    for (size_t i = 0; i < mine.size(); ++i) {
      if (m.yours[i] == Match::None && comparable(i)) take(reversed(mine[i].translated), i, Match::Reversed);
    }
  }
  return m;
}

// What is wrong with each of your cycles that has no same-orientation match; returns how many of them were not
// compared (a corner without a match).
size_t report_your_cycles(const std::vector<Cycle>& mine, const std::vector<Cycle>& theirs, const CycleMatching& m,
                          const CycleKinds& kinds, Collector& out) {
  size_t skipped = 0;
  for (size_t i = 0; i < mine.size(); ++i) {
    const Cycle& c = mine[i];
    if (m.yours[i] == Match::Same) continue;
    kinds.extra->push_back(c.face);
    if (c.broken) {
      out.add([&] { return tr_format(kinds.texts->your_broken, {{"face", format_id(c.face)}}); });
    } else if (c.translated.empty()) {
      ++skipped;
    } else if (m.yours[i] == Match::Reversed) {
      kinds.reversed->push_back(c.face);
      const Cycle& r = theirs[m.partner[i]];
      out.add([&] {
        return tr_format(kinds.texts->your_reversed, {{"face", format_id(c.face)},
                                                      {"corners", corners(c, Other::Reference)},
                                                      {"reference_face", format_id(r.face)},
                                                      {"reference_corners", corners(r, Other::Yours)}});
      });
    } else {
      out.add([&] {
        return tr_format(kinds.texts->your_extra,
                         {{"face", format_id(c.face)}, {"corners", corners(c, Other::Reference)}});
      });
    }
  }
  return skipped;
}

// The same for the reference's cycles none of yours matched; a reversed partner was told with yours.
size_t report_reference_cycles(const std::vector<Cycle>& theirs, const CycleMatching& m, const CycleKinds& kinds,
                               Collector& out) {
  size_t skipped = 0;
  for (size_t i = 0; i < theirs.size(); ++i) {
    const Cycle& r = theirs[i];
    if (m.theirs[i] == Match::Same) continue;
    kinds.missing->push_back(r.face);
    if (m.theirs[i] == Match::Reversed) continue;
    if (r.broken) {
      out.add([&] { return tr_format(kinds.texts->reference_broken, {{"face", format_id(r.face)}}); });
    } else if (r.translated.empty()) {
      ++skipped;
    } else {
      out.add([&] {
        return tr_format(kinds.texts->reference_missing,
                         {{"face", format_id(r.face)}, {"corners", corners(r, Other::Yours)}});
      });
    }
  }
  return skipped;
}

void compare_cycles(const HalfedgeMesh& yours, const HalfedgeMesh& reference, bool boundaries,
                    const std::vector<VertexId>& to_reference, const std::vector<VertexId>& to_yours,
                    const CycleKinds& kinds, Collector& out) {
  const auto range = [&](const HalfedgeMesh& m) { return boundaries ? m.boundaries() : m.faces(); };
  std::vector<Cycle> mine, theirs;
  for (FaceId f : range(yours)) mine.push_back(read_cycle(yours, f, to_reference));
  for (FaceId f : range(reference)) theirs.push_back(read_cycle(reference, f, to_yours));
  const CycleMatching matching = match_cycles(mine, theirs, kinds.reversed != nullptr);
  const size_t skipped_mine = report_your_cycles(mine, theirs, matching, kinds, out);
  const size_t skipped_theirs = report_reference_cycles(theirs, matching, kinds, out);
  if (skipped_mine + skipped_theirs > 0) {
    out.add([&] {
      return tr_format(kinds.texts->skipped,
                       {{"mine", std::to_string(skipped_mine)}, {"theirs", std::to_string(skipped_theirs)}});
    });
  }
}

struct EdgeEnds {
  EdgeId edge;
  uint32_t a = kInvalidIndex, b = kInvalidIndex;  // own ids
  Key translated;                                 // sorted pair in the other mesh's ids; empty if unmatched
  bool broken = false;
};

EdgeEnds read_edge(const HalfedgeMesh& mesh, EdgeId e, const std::vector<VertexId>& map) {
  EdgeEnds ends{e};
  const HalfedgeId h = mesh.halfedge(e);
  const HalfedgeId t = mesh.alive(h) ? mesh.twin(h) : HalfedgeId();
  if (!mesh.alive(h) || !mesh.alive(t) || !mesh.alive(mesh.vertex(h)) || !mesh.alive(mesh.vertex(t))) {
    ends.broken = true;
    return ends;
  }
  ends.a = mesh.vertex(h).index;
  ends.b = mesh.vertex(t).index;
  for (uint32_t v : {ends.a, ends.b}) {
    if (v >= map.size() || !map[v].valid()) {
      ends.translated.clear();
      return ends;
    }
    ends.translated.push_back(map[v].index);
  }
  std::sort(ends.translated.begin(), ends.translated.end());
  return ends;
}

std::string edge_ends(const EdgeEnds& e, Other other) {
  Key own{e.a, e.b};
  std::sort(own.begin(), own.end());
  return named_corners(format_id(VertexId(e.a)) + " " + format_id(VertexId(e.b)), e.translated, e.translated != own,
                       other);
}

void compare_edges(const HalfedgeMesh& yours, const HalfedgeMesh& reference, const std::vector<VertexId>& to_reference,
                   const std::vector<VertexId>& to_yours, MeshComparison& result, Collector& out) {
  std::vector<EdgeEnds> mine, theirs;
  for (EdgeId e : yours.edges()) mine.push_back(read_edge(yours, e, to_reference));
  for (EdgeId e : reference.edges()) theirs.push_back(read_edge(reference, e, to_yours));
  std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> by_key;
  for (size_t i = theirs.size(); i-- > 0;) {
    if (theirs[i].broken || theirs[i].translated.empty()) continue;
    by_key[{std::min(theirs[i].a, theirs[i].b), std::max(theirs[i].a, theirs[i].b)}].push_back(i);
  }
  std::vector<uint8_t> used(theirs.size(), 0);
  size_t skipped_mine = 0, skipped_theirs = 0;
  for (const EdgeEnds& e : mine) {
    if (!e.broken && !e.translated.empty()) {
      const auto it = by_key.find({e.translated[0], e.translated[1]});
      if (it != by_key.end() && !it->second.empty()) {
        used[it->second.back()] = 1;
        it->second.pop_back();
        continue;
      }
    }
    result.extra_edges.push_back(e.edge);
    if (e.broken) {
      out.add([&] {
        return tr_format("your edge {edge} cannot be read: its halfedge, twin or their vertices are dead",
                         {{"edge", format_id(e.edge)}});
      });
    } else if (e.translated.empty()) {
      ++skipped_mine;
    } else {
      out.add([&] {
        return tr_format("your edge {edge} {ends} is not in the reference",
                         {{"edge", format_id(e.edge)}, {"ends", edge_ends(e, Other::Reference)}});
      });
    }
  }
  for (size_t i = 0; i < theirs.size(); ++i) {
    const EdgeEnds& e = theirs[i];
    if (used[i]) continue;
    result.missing_edges.push_back(e.edge);
    if (e.broken) {
      out.add([&] { return tr_format("reference edge {edge} cannot be read", {{"edge", format_id(e.edge)}}); });
    } else if (e.translated.empty()) {
      ++skipped_theirs;
    } else {
      out.add([&] {
        return tr_format("reference edge {edge} {ends} is missing from yours",
                         {{"edge", format_id(e.edge)}, {"ends", edge_ends(e, Other::Yours)}});
      });
    }
  }
  if (skipped_mine + skipped_theirs > 0) {
    out.add([&] {
      return tr_format(
          "{mine} of your edges and {theirs} of the reference's touch a vertex without a match and were not compared",
          {{"mine", std::to_string(skipped_mine)}, {"theirs", std::to_string(skipped_theirs)}});
    });
  }
}

}  // namespace

// ---- public functions ------------------------------------------------------------------------------

double mesh_tolerance(const HalfedgeMesh& input) {
  glm::dvec3 lo(0.0), hi(0.0);
  bool first = true;
  for (VertexId v : input.vertices()) {
    const glm::dvec3& p = input.position(v);
    lo = first ? p : glm::min(lo, p);
    hi = first ? p : glm::max(hi, p);
    first = false;
  }
  const double diagonal = glm::distance(lo, hi);
  return 1e-9 * (std::isfinite(diagonal) ? std::max(1.0, diagonal) : 1.0);
}

double points_tolerance(std::span<const glm::dvec3> points) {
  double largest = 0.0;
  for (const glm::dvec3& p : points) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return 1e-9 * std::max(1.0, std::isfinite(largest) ? largest : 0.0);
}

std::string MeshComparison::summary() const {
  if (total_differences == 0) return tr("equal");
  const bool one = total_differences == 1;
  if (differences.empty()) {
    const MessageParts parts = {{"count", std::to_string(total_differences)}};
    return one ? tr_format("{count} difference", parts) : tr_format("{count} differences", parts);
  }
  const MessageParts parts = {{"count", std::to_string(total_differences)}, {"first", differences.front()}};
  return one ? tr_format("{count} difference; first: {first}", parts)
             : tr_format("{count} differences; first: {first}", parts);
}

MeshComparison compare_meshes_exact(const HalfedgeMesh& yours, const HalfedgeMesh& reference,
                                    const CompareOptions& options) {
  MeshComparison result;
  Collector out(result, options.max_differences);
  compare_counts(yours, reference, out);
  for (ElementKind kind :
       {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face, ElementKind::Boundary}) {
    const uint32_t slots = std::max(yours.capacity(kind), reference.capacity(kind));
    for (uint32_t i = 0; i < slots; ++i) {
      const ElementRef e(kind, i);
      const bool in_yours = yours.alive(e), in_reference = reference.alive(e);
      if (in_yours && in_reference) {
        compare_element(yours, reference, e, options.position_tolerance, out);
      } else if (in_yours) {
        out.add([&] { return tr_format("yours has {element}, the reference does not", {{"element", format_id(e)}}); });
      } else if (in_reference) {
        out.add([&] { return tr_format("the reference has {element}, yours does not", {{"element", format_id(e)}}); });
      }
    }
  }
  result.equal = result.total_differences == 0;
  return result;
}

MeshComparison compare_meshes(const HalfedgeMesh& yours, const HalfedgeMesh& reference, const CompareOptions& options) {
  MeshComparison result;
  Collector out(result, options.max_differences);
  compare_counts(yours, reference, out);

  // Pair vertices: every pair within the tolerance, nearest first, one to one.
  struct Pair {
    double distance;
    uint32_t yours, reference;
  };
  std::vector<Pair> pairs;
  const VertexGrid grid(reference, options.position_tolerance);
  for (VertexId v : yours.vertices()) {
    const glm::dvec3& p = yours.position(v);
    if (!finite(p)) continue;
    grid.for_each_near(p, [&](VertexId r, double d) { pairs.push_back({d, v.index, r.index}); });
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    return a.yours != b.yours ? a.yours < b.yours : a.reference < b.reference;
  });
  result.vertex_map.assign(yours.vertex_capacity(), VertexId());
  std::vector<VertexId> to_yours(reference.vertex_capacity(), VertexId());
  for (const Pair& p : pairs) {
    if (result.vertex_map[p.yours].valid() || to_yours[p.reference].valid()) continue;
    result.vertex_map[p.yours] = VertexId(p.reference);
    to_yours[p.reference] = VertexId(p.yours);
  }
  for (VertexId v : yours.vertices()) {
    if (result.vertex_map[v.index].valid()) continue;
    result.unmatched_vertices.push_back(v);
    out.add([&] { return no_match(yours, v, reference, to_yours, kYourVertex); });
  }
  for (VertexId v : reference.vertices()) {
    if (to_yours[v.index].valid()) continue;
    result.unmatched_reference.push_back(v);
    out.add([&] { return no_match(reference, v, yours, result.vertex_map, kReferenceVertex); });
  }

  compare_cycles(yours, reference, false, result.vertex_map, to_yours,
                 {&kFaceTexts, &result.extra_faces, &result.missing_faces, &result.reversed_faces}, out);
  compare_cycles(yours, reference, true, result.vertex_map, to_yours,
                 {&kBoundaryTexts, &result.extra_boundaries, &result.missing_boundaries, nullptr}, out);
  compare_edges(yours, reference, result.vertex_map, to_yours, result, out);
  result.equal = result.total_differences == 0;
  return result;
}

}  // namespace meshedit
