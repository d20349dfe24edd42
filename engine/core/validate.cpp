// validate(): finds every broken invariant listed in validate.h and reports it with element ids.
//
// Invariants this file keeps for itself, because the mesh under inspection may hold any value in any field:
// - No pointer is followed (no array indexed by an id) before `alive()` said the id is in range and live.
// - Every walk marks the halfedges it visits; a walk stops on reaching a marked halfedge, so each halfedge
//   is stepped on at most once per kind of walk (faces, fans), and the whole check is O(H + V + E + F)
//   plus O(k log cap) for k violations.
// - Checks run in the order of `Invariant`, elements in id order; the report keeps the `cap` smallest
//   (invariant, element, discovery order) keys in a bounded heap, so a mesh broken everywhere costs no
//   more memory than the cap, and messages past the cap are never even formatted.
// - One cause, one report where possible: a walk that meets a dead pointer stops silently, since the
//   DeadReference check already names that pointer.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   messages            bad_target, id_list, Path, Collector (the bounded heap of the smallest keys)
//   Validator           run: the checks below, in the order of Invariant
//   DeadReference       check_references, and who refers to whom
//   TwinOfTwin          check_twins
//   TwinEdge            check_edges
//   FaceCycle           check_faces, walk_face
//   NextNotPermutation  check_next_permutation
//   VertexHalfedge      check_vertex_halfedges
//   VertexFan           check_fans, walk_fan (and the all-boundary orphan)
//   Orphan              check_orphans
//   NonFinitePosition   check_positions
//   public functions    invariant_name, ValidationReport::summary, validate
#include "core/validate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/quick_check.h"
#include "core/translation.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

// ---- messages --------------------------------------------------------------------------------------

// Ids listed in one message, so a huge broken fan or cycle does not make a huge message.
constexpr size_t kListCap = 8;

// The message templates (tr_format, translated in assets/translations/*/core.po) are filled only inside the lambdas
// Collector::add calls for a violation it keeps, never for a valid mesh.

// "h99, past the end (48 halfedge slots)", one template per kind so a translation names the kind in its own words.
const char* past_the_end(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return "{element}, past the end ({count} vertex slots)";
    case ElementKind::Halfedge: return "{element}, past the end ({count} halfedge slots)";
    case ElementKind::Edge: return "{element}, past the end ({count} edge slots)";
    case ElementKind::Face: return "{element}, past the end ({count} face slots)";
    case ElementKind::Boundary: return "{element}, past the end ({count} boundary slots)";
  }
  return "{element}, past the end ({count} element slots)";
}

// Describes a reference that failed alive(): "- (none)", "h99, past the end (48 halfedge slots)",
// "h7, which is dead".
std::string bad_target(const HalfedgeMesh& m, ElementRef r) {
  if (!r.valid()) return tr("- (none)");
  const uint32_t slots = m.capacity(r.kind);
  if (r.index >= slots) {
    return tr_format(past_the_end(r.kind), {{"element", format_id(r)}, {"count", std::to_string(slots)}});
  }
  return tr_format("{element}, which is dead", {{"element", format_id(r)}});
}

// "h3 h9 h20", or "h3 h9 ... (40 more)" past kListCap.
std::string id_list(const std::vector<HalfedgeId>& ids, size_t total) {
  std::string s;
  for (size_t i = 0; i < ids.size() && i < kListCap; ++i) {
    if (i > 0) s += ' ';
    s += format_id(ids[i]);
  }
  if (total > kListCap) {
    return tr_format("{ids} ... ({count} more)", {{"ids", s}, {"count", std::to_string(total - kListCap)}});
  }
  return s;
}

// A walk's path, remembered only as far as messages print it.
struct Path {
  std::vector<HalfedgeId> ids;
  size_t length = 0;
  void clear() {
    ids.clear();
    length = 0;
  }
  void push(HalfedgeId h) {
    if (ids.size() < kListCap) ids.push_back(h);
    ++length;
  }
  std::string str() const { return id_list(ids, length); }
};

// Keeps the `cap` first violations in report order; counts all of them.
class Collector {
 public:
  explicit Collector(size_t cap) : cap_(cap) {}

  template <class MakeMessage>
  void add(Invariant invariant, ElementRef element, MakeMessage&& make_message) {
    const Key key{invariant, element, total_++};
    if (cap_ == 0) return;
    if (heap_.size() == cap_ && !(key < heap_.front().key)) return;
    heap_.push_back({key, Violation{element, invariant, make_message()}});
    std::push_heap(heap_.begin(), heap_.end());
    if (heap_.size() > cap_) {
      std::pop_heap(heap_.begin(), heap_.end());
      heap_.pop_back();
    }
  }

  ValidationReport finish() {
    std::sort_heap(heap_.begin(), heap_.end());
    ValidationReport report;
    report.total = total_;
    report.violations.reserve(heap_.size());
    for (auto& entry : heap_) report.violations.push_back(std::move(entry.violation));
    return report;
  }

 private:
  struct Key {
    Invariant invariant;
    ElementRef element;
    size_t order;
    friend bool operator<(const Key& a, const Key& b) {
      if (a.invariant != b.invariant) return a.invariant < b.invariant;
      if (a.element != b.element) return a.element < b.element;
      return a.order < b.order;
    }
  };
  struct Entry {
    Key key;
    Violation violation;
    friend bool operator<(const Entry& a, const Entry& b) { return a.key < b.key; }
  };
  size_t cap_;
  size_t total_ = 0;
  std::vector<Entry> heap_;  // max-heap on key: the front is the first to drop
};

// ---- Validator -------------------------------------------------------------------------------------

class Validator {
 public:
  Validator(const HalfedgeMesh& mesh, size_t cap) : m_(mesh), out_(cap) {}

  ValidationReport run() {
    check_references();
    check_twins();
    check_edges();
    check_faces();
    check_next_permutation();
    check_vertex_halfedges();
    check_fans();
    check_orphans();
    check_positions();
    return out_.finish();
  }

 private:
  // The raw index of a face or boundary loop, for per-face tables (faces first, then boundary loops).
  uint32_t face_slot(FaceId f) const { return f.is_boundary() ? m_.face_capacity() + f.slot() : f.slot(); }

  template <class Fn>
  void for_each_face_and_boundary(Fn&& fn) const {
    for (FaceId f : m_.faces()) fn(f);
    for (FaceId b : m_.boundaries()) fn(b);
  }

  // ---- DeadReference, and who refers to whom (for the permutation and orphan checks) -------------
  void check_references() {
    next_count_.assign(m_.halfedge_capacity(), 0);
    leaving_.assign(m_.vertex_capacity(), 0);
    on_edge_.assign(m_.edge_capacity(), 0);
    in_face_.assign(size_t(m_.face_capacity()) + m_.boundary_capacity(), 0);

    auto dead = [&](ElementRef owner, const char* field, ElementRef target) {
      out_.add(Invariant::DeadReference, owner, [&] {
        return tr_format("{element}.{field} is {target}",
                         {{"element", format_id(owner)}, {"field", field}, {"target", bad_target(m_, target)}});
      });
    };
    for (HalfedgeId h : m_.halfedges()) {
      const HalfedgeId n = m_.next(h), t = m_.twin(h);
      const VertexId v = m_.vertex(h);
      const EdgeId e = m_.edge(h);
      const FaceId f = m_.face(h);
      if (m_.alive(n)) ++next_count_[n.index];
      else dead(h, "next", n);
      if (!m_.alive(t)) dead(h, "twin", t);
      if (m_.alive(v)) ++leaving_[v.index];
      else dead(h, "vertex", v);
      if (m_.alive(e)) ++on_edge_[e.index];
      else dead(h, "edge", e);
      if (m_.alive(f)) ++in_face_[face_slot(f)];
      else dead(h, "face", f);
    }
    for (VertexId v : m_.vertices()) {
      if (!m_.alive(m_.halfedge(v))) dead(v, "halfedge", m_.halfedge(v));
    }
    for (EdgeId e : m_.edges()) {
      if (!m_.alive(m_.halfedge(e))) dead(e, "halfedge", m_.halfedge(e));
    }
    for_each_face_and_boundary([&](FaceId f) {
      if (!m_.alive(m_.halfedge(f))) dead(f, "halfedge", m_.halfedge(f));
    });
  }

  // ---- TwinOfTwin ---------------------------------------------------------------------------------
  void check_twins() {
    for (HalfedgeId h : m_.halfedges()) {
      const HalfedgeId t = m_.twin(h);
      if (!m_.alive(t)) continue;
      if (t == h) {
        out_.add(Invariant::TwinOfTwin, h, [&] {
          return tr_format("{halfedge}.twin is {halfedge} itself", {{"halfedge", format_id(h)}});
        });
      } else if (m_.twin(t) != h) {
        out_.add(Invariant::TwinOfTwin, h, [&] {
          return tr_format("{halfedge}.twin is {twin}, but {twin}.twin is {other} (should be {halfedge})",
                           {{"halfedge", format_id(h)}, {"twin", format_id(t)}, {"other", format_id(m_.twin(t))}});
        });
      }
    }
  }

  // ---- TwinEdge -----------------------------------------------------------------------------------
  // With twins paired, "twins share their edge", "e.halfedge lies on e" and "no edge has more than two
  // halfedges" together say that e's halfedges are exactly e.halfedge and its twin.
  void check_edges() {
    for (HalfedgeId h : m_.halfedges()) {
      const HalfedgeId t = m_.twin(h);
      if (!m_.alive(t) || t == h || m_.twin(t) != h || t < h) continue;  // unpaired twins: TwinOfTwin
      if (m_.edge(h) != m_.edge(t)) {
        out_.add(Invariant::TwinEdge, h, [&] {
          return tr_format("{halfedge} and its twin {twin} lie on different edges ({edge} and {twin_edge})",
                           {{"halfedge", format_id(h)},
                            {"twin", format_id(t)},
                            {"edge", format_id(m_.edge(h))},
                            {"twin_edge", format_id(m_.edge(t))}});
        });
      }
    }
    for (EdgeId e : m_.edges()) {
      const HalfedgeId s = m_.halfedge(e);
      if (m_.alive(s) && m_.edge(s) != e) {
        out_.add(Invariant::TwinEdge, e, [&] {
          return tr_format("{edge}.halfedge is {halfedge}, but {halfedge}.edge is {other}",
                           {{"edge", format_id(e)}, {"halfedge", format_id(s)}, {"other", format_id(m_.edge(s))}});
        });
      }
    }
    bool crowded = false;
    for (EdgeId e : m_.edges()) crowded = crowded || on_edge_[e.index] > 2;
    if (!crowded) return;
    std::map<uint32_t, std::vector<HalfedgeId>> lists;
    for (HalfedgeId h : m_.halfedges()) {
      const EdgeId e = m_.edge(h);
      if (m_.alive(e) && on_edge_[e.index] > 2 && lists[e.index].size() < kListCap) lists[e.index].push_back(h);
    }
    // Named variables, not structured bindings: the lambda captures them, which clang before 16 (and older Apple
    // toolchains) refuse for bindings.
    for (const auto& entry : lists) {
      const uint32_t index = entry.first;
      const std::vector<HalfedgeId>& list = entry.second;
      const EdgeId e(index);
      out_.add(Invariant::TwinEdge, e, [&] {  // more than two, so always "halfedges"
        return tr_format("{edge} has {count} halfedges ({halfedges}); an edge has exactly two",
                         {{"edge", format_id(e)},
                          {"count", std::to_string(on_edge_[index])},
                          {"halfedges", id_list(list, on_edge_[index])}});
      });
    }
  }

  // ---- FaceCycle ----------------------------------------------------------------------------------
  // Each halfedge is claimed by the first face walk that reaches it; a walk that reaches a halfedge
  // claimed by another face is broken (a valid mesh's cycles are disjoint), so no halfedge is walked twice.
  void check_faces() {
    face_owner_.assign(m_.halfedge_capacity(), FaceId());
    face_closed_.assign(size_t(m_.face_capacity()) + m_.boundary_capacity(), 0);
    for_each_face_and_boundary([&](FaceId f) { walk_face(f); });
    // A halfedge must lie in the cycle of the face it names: report it when it sits in another face's
    // closed cycle, or when its own face's cycle closed without it. A halfedge swallowed by a walk that
    // broke (a rho running through other faces) is left to that walk's report, to keep one cause one report.
    for (HalfedgeId h : m_.halfedges()) {
      const FaceId f = m_.face(h);
      const FaceId owner = face_owner_[h.index];
      if (!m_.alive(f) || owner == f) continue;
      if (owner.valid()) {
        if (!face_closed_[face_slot(owner)]) continue;
        out_.add(Invariant::FaceCycle, h, [&] {
          return tr_format("{halfedge}.face is {face}, but {halfedge} is in {owner}'s next-cycle",
                           {{"halfedge", format_id(h)}, {"face", format_id(f)}, {"owner", format_id(owner)}});
        });
      } else if (face_closed_[face_slot(f)]) {
        out_.add(Invariant::FaceCycle, h, [&] {
          return tr_format("{halfedge}.face is {face}, but {halfedge} is not in {face}'s next-cycle",
                           {{"halfedge", format_id(h)}, {"face", format_id(f)}});
        });
      }
    }
  }

  void walk_face(FaceId f) {
    const HalfedgeId s = m_.halfedge(f);
    if (!m_.alive(s)) return;  // DeadReference
    if (m_.face(s) != f) {
      out_.add(Invariant::FaceCycle, f, [&] {
        return tr_format("{face}.halfedge is {halfedge}, but {halfedge}.face is {other}",
                         {{"face", format_id(f)}, {"halfedge", format_id(s)}, {"other", format_id(m_.face(s))}});
      });
      return;
    }
    Path& path = scratch_;
    path.clear();
    HalfedgeId h = s;
    for (;;) {
      const FaceId owner = face_owner_[h.index];
      if (owner == f) {
        if (h == s) break;  // closed
        out_.add(Invariant::FaceCycle, f, [&] {
          return tr_format(
              "{face}'s next-cycle does not close: {path} then comes back to {halfedge}, never to {face}.halfedge "
              "{start}",
              {{"face", format_id(f)}, {"path", path.str()}, {"halfedge", format_id(h)}, {"start", format_id(s)}});
        });
        return;
      }
      if (owner.valid()) {
        out_.add(Invariant::FaceCycle, f, [&] {
          const MessageParts parts = {
              {"face", format_id(f)}, {"path", path.str()}, {"halfedge", format_id(h)}, {"owner", format_id(owner)}};
          return path.length == 0
                     ? tr_format(
                           "{face}'s next-cycle does not close: it reaches {halfedge}, which is in {owner}'s "
                           "next-cycle",
                           parts)
                     : tr_format(
                           "{face}'s next-cycle does not close: {path} then it reaches {halfedge}, which is in "
                           "{owner}'s next-cycle",
                           parts);
        });
        return;
      }
      face_owner_[h.index] = f;
      path.push(h);  // a halfedge of another face here is reported by check_faces
      const HalfedgeId n = m_.next(h);
      if (!m_.alive(n)) return;  // DeadReference names h.next
      h = n;
    }
    face_closed_[face_slot(f)] = 1;
    if (path.length < 3) {
      out_.add(Invariant::FaceCycle, f, [&] {
        const MessageParts parts = {
            {"face", format_id(f)}, {"count", std::to_string(path.length)}, {"path", path.str()}};
        if (f.is_boundary()) {
          return path.length == 1
                     ? tr_format(
                           "{face}'s next-cycle has only {count} halfedge ({path}); a boundary loop needs at "
                           "least 3",
                           parts)
                     : tr_format(
                           "{face}'s next-cycle has only {count} halfedges ({path}); a boundary loop needs at "
                           "least 3",
                           parts);
        }
        if (path.length == 1) {
          return tr_format("{face}'s next-cycle has only {count} halfedge ({path}); a face needs at least 3", parts);
        }
        return tr_format("{face}'s next-cycle has only {count} halfedges ({path}); a face needs at least 3", parts);
      });
    }
  }

  // ---- NextNotPermutation -------------------------------------------------------------------------
  void check_next_permutation() {
    std::map<uint32_t, std::vector<HalfedgeId>> shared;  // halfedges that are the next of several
    for (HalfedgeId h : m_.halfedges()) {
      if (next_count_[h.index] > 1) shared[h.index];
    }
    if (!shared.empty()) {
      for (HalfedgeId h : m_.halfedges()) {
        const HalfedgeId n = m_.next(h);
        if (!m_.alive(n) || next_count_[n.index] < 2) continue;
        auto& list = shared[n.index];
        if (list.size() < kListCap) list.push_back(h);
      }
    }
    for (HalfedgeId h : m_.halfedges()) {
      const uint32_t count = next_count_[h.index];
      if (count == 1) continue;
      out_.add(Invariant::NextNotPermutation, h, [&] {
        if (count == 0) return tr_format("no live halfedge has {halfedge} as its next", {{"halfedge", format_id(h)}});
        return tr_format("{halfedge} is the next of {count} halfedges ({halfedges})",  // count >= 2
                         {{"halfedge", format_id(h)},
                          {"count", std::to_string(count)},
                          {"halfedges", id_list(shared[h.index], count)}});
      });
    }
  }

  // ---- VertexHalfedge -----------------------------------------------------------------------------
  void check_vertex_halfedges() {
    for (VertexId v : m_.vertices()) {
      const HalfedgeId s = m_.halfedge(v);
      if (m_.alive(s) && m_.vertex(s) != v) {
        out_.add(Invariant::VertexHalfedge, v, [&] {
          return tr_format("{vertex}.halfedge is {halfedge}, but {halfedge} leaves {other}",
                           {{"vertex", format_id(v)}, {"halfedge", format_id(s)}, {"other", format_id(m_.vertex(s))}});
        });
      }
    }
  }

  // ---- VertexFan (and the all-boundary orphan, found on the same walk) -----------------------------
  // A fan walk only steps onto halfedges that leave its vertex, so each halfedge is visited by at most
  // one vertex's walk.
  void check_fans() {
    fan_owner_.assign(m_.halfedge_capacity(), VertexId());
    std::vector<uint8_t> fan_closed(m_.vertex_capacity(), 0);
    for (VertexId v : m_.vertices()) {
      if (walk_fan(v)) fan_closed[v.index] = 1;
    }
    // Halfedges leaving a vertex whose fan closed without them: the vertex has several fans.
    std::map<uint32_t, std::vector<Path>> others;
    for (HalfedgeId h : m_.halfedges()) {
      const VertexId v = m_.vertex(h);
      if (!m_.alive(v) || !fan_closed[v.index] || fan_owner_[h.index].valid()) continue;
      Path group;
      HalfedgeId g = h;
      while (!fan_owner_[g.index].valid()) {
        fan_owner_[g.index] = v;
        group.push(g);
        const HalfedgeId t = m_.twin(g);
        if (!m_.alive(t)) break;
        const HalfedgeId n = m_.next(t);
        if (!m_.alive(n) || m_.vertex(n) != v) break;
        g = n;
      }
      others[v.index].push_back(std::move(group));
    }
    for (const auto& entry : others) {  // not a structured binding: the lambda captures `groups` (see check_edges)
      const std::vector<Path>& groups = entry.second;
      const VertexId v(entry.first);
      out_.add(Invariant::VertexFan, v, [&] {
        // The first fan closed, so walking it again ends.
        Path first;
        const HalfedgeId start = m_.halfedge(v);
        HalfedgeId g = start;
        do {
          first.push(g);
          g = m_.next(m_.twin(g));
        } while (g != start);
        const size_t count = groups.size() + 1;
        std::string fans = first.str();
        for (const Path& group : groups) fans += " | " + group.str();
        const MessageParts parts = {{"vertex", format_id(v)}, {"count", std::to_string(count)}, {"fans", fans}};
        return count == 2 ? tr_format("{vertex} has two separate fans (hourglass): {fans}", parts)
                          : tr_format("{vertex} has {count} separate fans (hourglass): {fans}", parts);
      });
    }
  }

  // Walks v's fan from v.halfedge; true if it closes.
  bool walk_fan(VertexId v) {
    const HalfedgeId s = m_.halfedge(v);
    if (!m_.alive(s) || m_.vertex(s) != v) return false;  // DeadReference, VertexHalfedge
    Path& path = scratch_;
    path.clear();
    std::vector<HalfedgeId>& boundary = boundary_scratch_;
    boundary.clear();
    bool has_face = false;
    HalfedgeId h = s;
    for (;;) {
      if (fan_owner_[h.index] == v) {
        if (h == s) break;
        out_.add(Invariant::VertexFan, v, [&] {
          return tr_format(
              "{vertex}'s fan does not close: {path} then comes back to {halfedge}, never to {vertex}.halfedge "
              "{start}",
              {{"vertex", format_id(v)}, {"path", path.str()}, {"halfedge", format_id(h)}, {"start", format_id(s)}});
        });
        return false;
      }
      fan_owner_[h.index] = v;
      path.push(h);
      const FaceId f = m_.face(h);
      if (f.is_boundary()) {
        boundary.push_back(h);
      } else if (f.valid()) {
        has_face = true;
      }
      const HalfedgeId t = m_.twin(h);
      if (!m_.alive(t)) return false;  // DeadReference
      const HalfedgeId n = m_.next(t);
      if (!m_.alive(n)) return false;  // DeadReference
      if (m_.vertex(n) != v) {
        out_.add(Invariant::VertexFan, v, [&] {
          return tr_format(
              "{vertex}'s fan does not close: {halfedge}.twin is {twin}, whose next {next} leaves {other}, not "
              "{vertex}",
              {{"vertex", format_id(v)},
               {"halfedge", format_id(h)},
               {"twin", format_id(t)},
               {"next", format_id(n)},
               {"other", format_id(m_.vertex(n))}});
        });
        return false;
      }
      h = n;
    }
    if (boundary.size() > 1) {
      out_.add(Invariant::VertexFan, v, [&] {
        std::string list;  // "h3 (b0) h9 (b1)": at least two
        for (size_t i = 0; i < boundary.size() && i < kListCap; ++i) {
          list += (i == 0 ? "" : " ") + format_id(boundary[i]) + " (" + format_id(m_.face(boundary[i])) + ")";
        }
        return tr_format(
            "{vertex} is on the boundary more than once: {halfedges}; at most one boundary halfedge may leave a vertex",
            {{"vertex", format_id(v)}, {"halfedges", list}});
      });
    }
    if (!has_face) {
      out_.add(Invariant::Orphan, v, [&] {
        return tr_format("{vertex} is orphaned: every face around it is a boundary loop", {{"vertex", format_id(v)}});
      });
    }
    return true;
  }

  // ---- Orphan -------------------------------------------------------------------------------------
  void check_orphans() {
    for (VertexId v : m_.vertices()) {
      if (leaving_[v.index] == 0) {
        out_.add(Invariant::Orphan, v, [&] {
          return tr_format("{vertex} is orphaned: no live halfedge leaves it", {{"vertex", format_id(v)}});
        });
      }
    }
    for (EdgeId e : m_.edges()) {
      if (on_edge_[e.index] == 0) {
        out_.add(Invariant::Orphan, e, [&] {
          return tr_format("{edge} is orphaned: no live halfedge lies on it", {{"edge", format_id(e)}});
        });
        continue;
      }
      const HalfedgeId s = m_.halfedge(e);
      if (!m_.alive(s) || m_.edge(s) != e) continue;
      const HalfedgeId t = m_.twin(s);
      if (!m_.alive(t) || t == s || m_.twin(t) != s) continue;
      if (m_.face(s).is_boundary() && m_.face(t).is_boundary()) {
        out_.add(Invariant::Orphan, e, [&] {
          return tr_format("{edge} is orphaned: both its sides are boundary loops ({loop} and {other})",
                           {{"edge", format_id(e)}, {"loop", format_id(m_.face(s))}, {"other", format_id(m_.face(t))}});
        });
      }
    }
    for_each_face_and_boundary([&](FaceId f) {
      if (in_face_[face_slot(f)] == 0) {
        out_.add(Invariant::Orphan, f, [&] {
          return tr_format("{face} is orphaned: no live halfedge lies in it", {{"face", format_id(f)}});
        });
      }
    });
  }

  // ---- NonFinitePosition --------------------------------------------------------------------------
  void check_positions() {
    for (VertexId v : m_.vertices()) {
      const glm::dvec3& p = m_.position(v);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        out_.add(Invariant::NonFinitePosition, v, [&] {
          return tr_format("{vertex}.position is {position}",
                           {{"vertex", format_id(v)}, {"position", format_position(p)}});
        });
      }
    }
  }

  const HalfedgeMesh& m_;
  Collector out_;
  std::vector<uint32_t> next_count_;  // per halfedge: live halfedges whose next it is
  std::vector<uint32_t> leaving_;     // per vertex: live halfedges leaving it
  std::vector<uint32_t> on_edge_;     // per edge: live halfedges on it
  std::vector<uint32_t> in_face_;     // per face_slot(): live halfedges in it
  std::vector<FaceId> face_owner_;    // per halfedge: the face whose walk claimed it
  std::vector<uint8_t> face_closed_;  // per face_slot(): its walk closed (perhaps too short)
  std::vector<VertexId> fan_owner_;   // per halfedge: the vertex whose fan walk reached it
  Path scratch_;                      // the current walk (reused: no allocation per face or vertex)
  std::vector<HalfedgeId> boundary_scratch_;
};

}  // namespace

// ---- public functions ------------------------------------------------------------------------------

const char* invariant_name(Invariant invariant) {
  switch (invariant) {
    case Invariant::DeadReference: return "dead reference";
    case Invariant::TwinOfTwin: return "twin of twin";
    case Invariant::TwinEdge: return "twin edge";
    case Invariant::FaceCycle: return "face cycle";
    case Invariant::NextNotPermutation: return "next not permutation";
    case Invariant::VertexHalfedge: return "vertex halfedge";
    case Invariant::VertexFan: return "vertex fan";
    case Invariant::Orphan: return "orphan";
    case Invariant::NonFinitePosition: return "non-finite position";
  }
  return "unknown";
}

std::string ValidationReport::summary() const {
  if (total == 0) return tr("valid");  // translated in ui.po (the status line's "valid")
  const MessageParts parts = {{"count", std::to_string(total)}};
  if (violations.empty()) {
    return total == 1 ? tr_format("{count} problem", parts) : tr_format("{count} problems", parts);
  }
  const MessageParts with_first = {{"count", std::to_string(total)}, {"first", violations.front().message}};
  return total == 1 ? tr_format("{count} problem; first: {first}", with_first)
                    : tr_format("{count} problems; first: {first}", with_first);
}

ValidationReport validate(const HalfedgeMesh& mesh, size_t max_violations, int threads) {
  if (mesh_is_clean(mesh, threads)) return {};  // quick_check.h: a sufficient test, so a valid mesh skips the full walk
  return Validator(mesh, max_violations).run();
}

ValidationReport validate_without_shortcut(const HalfedgeMesh& mesh, size_t max_violations) {
  return Validator(mesh, max_violations).run();
}

}  // namespace meshedit
