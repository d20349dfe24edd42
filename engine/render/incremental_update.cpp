// Incremental updates of the slot layout (see incremental_update.h for the rules and why they are complete).
//
// Invariant: every search backwards along a pointer ends with a count check against MeshReferences; a search that
// cannot prove it found everything makes the whole update a full rebuild, never a partial one.
#include "render/incremental_update.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/finite.h"

namespace meshedit {
namespace {

void sort_unique(std::vector<uint32_t>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// The halfedges leaving u, found by walking its fan (twin, then next) from u.halfedge, into `out`; true when the walk
// closed after exactly `outgoing` distinct halfedges that all leave u (then there is no other: `outgoing` counts
// them). A walk first back at its start after k steps has visited k distinct halfedges. `Mesh`: a HalfedgeMesh, or the
// StateBefore of an edit.
template <class Mesh>
bool fan(const Mesh& mesh, VertexId u, uint32_t outgoing, std::vector<HalfedgeId>& out) {
  out.clear();
  if (outgoing == 0) return true;
  if (outgoing > kMaxWalk || u.index >= mesh.vertex_capacity()) return false;
  const HalfedgeId start = mesh.halfedge(u);
  HalfedgeId h = start;
  for (uint32_t i = 0; i < outgoing; ++i) {
    if (i > 0 && h == start) return false;
    if (!mesh.alive(h) || mesh.vertex(h) != u) return false;
    out.push_back(h);
    const HalfedgeId t = mesh.twin(h);
    if (!mesh.alive(t)) return false;
    h = mesh.next(t);
  }
  return h == start;
}

// Adds `candidate` to `found` when it satisfies `test` and is not there yet.
template <class Test>
void consider(uint32_t candidate, std::vector<uint32_t>& found, Test&& test) {
  if (candidate == kInvalidIndex || !test(candidate)) return;
  if (std::find(found.begin(), found.end(), candidate) == found.end()) found.push_back(candidate);
}

// The changed elements of each kind, sorted, each once. Boundary loops are left out: nothing drawn reads them.
struct ChangedIds {
  std::vector<uint32_t> vertices, halfedges, edges, faces;
};

ChangedIds sorted_changes(std::span<const ElementRef> changed) {
  ChangedIds ids;
  for (const ElementRef& ref : changed) {
    if (!ref.valid()) continue;
    switch (ref.kind) {
      case ElementKind::Vertex: ids.vertices.push_back(ref.index); break;
      case ElementKind::Halfedge: ids.halfedges.push_back(ref.index); break;
      case ElementKind::Edge: ids.edges.push_back(ref.index); break;
      case ElementKind::Face: ids.faces.push_back(ref.index); break;
      case ElementKind::Boundary: break;
    }
  }
  for (auto* list : {&ids.vertices, &ids.halfedges, &ids.edges, &ids.faces}) sort_unique(*list);
  return ids;
}

// plan_update's work, one step per kind of slot (see plan() for their order). A step that cannot certify what it
// found fails with the reason in `why`, and the update is a full rebuild.
template <class Before>
struct Planner {
  const Before& before;
  const HalfedgeMesh& after;
  SlotState& state;
  std::string& why;
  bool arrows;  // the patch rewrites the arrows too

  // Dirty slots, by kind. Faces and edges are found from `before`'s pointers and counts (what did not change reads
  // the same in both states); vertices and arrows from the faces drawn.
  std::vector<uint32_t> dirty_faces, dirty_edges, dirty_vertices, dirty_arrows;
  std::vector<uint32_t> leaving_changed;               // the halfedges leaving a changed vertex in `before`
  std::unordered_map<uint32_t, FaceDraw> drawn_after;  // faces drawn in `after`, by slot
  SlotPatch patch;
  std::vector<HalfedgeId> walk;      // scratch: the cycle of the face drawn last
  std::vector<HalfedgeId> fan_walk;  // scratch: the fan walked last

  bool fail(std::string reason) {
    why = std::move(reason);
    return false;
  }

  // The halfedges leaving v in `mesh`, into fan_walk (certified by the outgoing counts of `state`).
  template <class Mesh>
  bool walk_fan(const Mesh& mesh, uint32_t v) {
    return fan(mesh, VertexId(v), state.references.outgoing[v], fan_walk) ||
           fail("the fan of " + format_id(VertexId(v)) + " does not hold every halfedge leaving it");
  }

  // The halfedges y of `before` with twin(y) == t (certified by the twin counts of `before`), into `out`.
  bool twins_of(uint32_t t, std::vector<uint32_t>& out) {
    out.clear();
    const auto test = [&](uint32_t y) { return before.alive(HalfedgeId(y)) && before.twin(HalfedgeId(y)).index == t; };
    if (t < before.halfedge_capacity()) consider(before.twin(HalfedgeId(t)).index, out, test);
    if (t < after.halfedge_capacity()) consider(after.twin(HalfedgeId(t)).index, out, test);
    const uint32_t expected = t < state.references.twin_refs.size() ? state.references.twin_refs[t] : 0;
    return out.size() == expected || fail(format_id(HalfedgeId(t)) + " is the twin of halfedges not found");
  }

  // The edges e of `before` with halfedge(e) == h (certified by the edge counts of `before`), appended to `out`.
  bool edges_of(uint32_t h, std::vector<uint32_t>& out) {
    std::vector<uint32_t> found;
    const auto test = [&](uint32_t e) { return before.alive(EdgeId(e)) && before.halfedge(EdgeId(e)).index == h; };
    const auto candidates_in = [&](const auto& m) {
      if (h >= m.halfedge_capacity()) return;
      consider(m.edge(HalfedgeId(h)).index, found, test);
      const HalfedgeId t = m.twin(HalfedgeId(h));
      if (t.index < m.halfedge_capacity()) consider(m.edge(t).index, found, test);
    };
    candidates_in(before);
    candidates_in(after);
    const uint32_t expected = h < state.references.edge_refs.size() ? state.references.edge_refs[h] : 0;
    if (found.size() != expected) return fail(format_id(HalfedgeId(h)) + " is the halfedge of edges not found");
    out.insert(out.end(), found.begin(), found.end());
    return true;
  }

  template <class Mesh>
  bool draw(const Mesh& mesh, uint32_t f, FaceDraw& d) {
    d = FaceDraw();
    walk.clear();
    if (f >= mesh.face_capacity()) return true;
    draw_face(mesh, FaceId::face(f), d, walk, nullptr, kMaxWalk);
    if (d.walk == FaceWalk::TooLong) return fail(format_id(FaceId::face(f)) + " is longer than the walk limit");
    return true;
  }

  // Dirty faces: the changed ones, those a changed halfedge lies in (in either state), and those around a changed
  // vertex in `before` (a new vertex: whatever leaves it in `after` is new or changed).
  bool find_dirty_faces(const ChangedIds& changed) {
    dirty_faces = changed.faces;
    const auto add_face = [&](FaceId f) {
      if (f.valid() && !f.is_boundary()) dirty_faces.push_back(f.slot());
    };
    for (uint32_t h : changed.halfedges) {
      if (h < before.halfedge_capacity()) add_face(before.face(HalfedgeId(h)));
      if (h < after.halfedge_capacity()) add_face(after.face(HalfedgeId(h)));
    }
    for (uint32_t u : changed.vertices) {
      if (u >= before.vertex_capacity()) continue;
      if (!walk_fan(before, u)) return false;
      for (HalfedgeId x : fan_walk) {
        add_face(before.face(x));
        leaving_changed.push_back(x.index);
      }
    }
    sort_unique(dirty_faces);
    return true;
  }

  // Dirty edges: edges read their halfedge h and twin(h), so those of the changed halfedges and of the halfedges
  // ending at a changed vertex, and those of their twins (a new halfedge: the edges and twins pointing at it changed
  // too).
  bool find_dirty_edges(const ChangedIds& changed) {
    dirty_edges = changed.edges;
    std::vector<uint32_t> reach = changed.halfedges, twins;
    reach.insert(reach.end(), leaving_changed.begin(), leaving_changed.end());
    sort_unique(reach);
    for (uint32_t h : reach) {
      if (h >= before.halfedge_capacity()) continue;
      if (!edges_of(h, dirty_edges) || !twins_of(h, twins)) return false;
      for (uint32_t y : twins) {
        if (!edges_of(y, dirty_edges)) return false;
      }
    }
    sort_unique(dirty_edges);
    return true;
  }

  // Faces: triangles and flat normals; their corners' smooth normals and their halfedges' arrows become dirty.
  bool redraw_faces(const ChangedIds& changed) {
    dirty_vertices = changed.vertices;
    FaceDraw old_draw;
    for (uint32_t f : dirty_faces) {
      if (!redraw_face(f, old_draw)) return false;
    }
    return true;
  }

  bool redraw_face(uint32_t f, FaceDraw& old_draw) {
    FaceDraw& new_draw = drawn_after[f];
    if (!draw(before, f, old_draw)) return false;
    mark_walked_arrows();
    if (!draw(after, f, new_draw)) return false;
    mark_walked_arrows();
    dirty_vertices.insert(dirty_vertices.end(), old_draw.corners.begin(), old_draw.corners.end());
    dirty_vertices.insert(dirty_vertices.end(), new_draw.corners.begin(), new_draw.corners.end());
    SlotCounts& counts = state.counts;
    if (before.alive(FaceId::face(f))) {
      if (old_draw.drawn()) counts.triangles -= old_draw.triangle_count();
      else --counts.skipped_faces;
    }
    if (after.alive(FaceId::face(f))) {
      if (new_draw.drawn()) counts.triangles += new_draw.triangle_count();
      else ++counts.skipped_faces;
    }
    if (!rewrite_later_triangles(f, old_draw, new_draw)) return false;
    if (f >= after.face_capacity()) return true;
    FacePatch fp{f, {0, 0, 0}, flat_normal(new_draw.term)};
    if (new_draw.drawn()) fp.triangle = {new_draw.corners[0], new_draw.corners[1], new_draw.corners[2]};
    patch.faces.push_back(fp);
    return true;
  }

  // The arrows of the face just drawn (its cycle, in `walk`) are dirty, when the patch rewrites arrows.
  void mark_walked_arrows() {
    if (!arrows) return;
    for (HalfedgeId h : walk) dirty_arrows.push_back(h.index);
  }

  // A polygon keeps its packed later triangles where they are only if it has as many as before.
  bool rewrite_later_triangles(uint32_t f, const FaceDraw& old_draw, const FaceDraw& new_draw) {
    const size_t extra = new_draw.triangle_count() > 0 ? new_draw.triangle_count() - 1 : 0;
    const size_t old_extra = old_draw.triangle_count() > 0 ? old_draw.triangle_count() - 1 : 0;
    if (extra != old_extra) return fail(format_id(FaceId::face(f)) + " has another number of triangles");
    for (size_t i = 0; i < extra; ++i) {
      const std::vector<uint32_t>& c = new_draw.corners;
      patch.extra_triangles.push_back({state.extra_first[f] + uint32_t(i), {c[0], c[i + 2], c[i + 3]}});
    }
    return true;
  }

  // Points (and positions) of the changed vertices.
  void rewrite_points(const ChangedIds& changed) {
    for (uint32_t v : changed.vertices) {
      if (v < before.vertex_capacity() && slot_point(before, VertexId(v)).vertex != kInvalidIndex) {
        --state.counts.vertices;
      }
      if (v >= after.vertex_capacity()) continue;
      const VertexPoint point = slot_point(after, VertexId(v));
      if (point.vertex != kInvalidIndex) {
        ++state.counts.vertices;
        state.bounds.add(after.position(VertexId(v)));
      }
      patch.points.emplace_back(v, point);
    }
  }

  // Smooth normals of the dirty vertices.
  bool rewrite_smooth_normals() {
    sort_unique(dirty_vertices);
    std::vector<CornerFace> corner_faces;
    for (uint32_t v : dirty_vertices) {
      if (v >= after.vertex_capacity()) continue;
      glm::vec3 normal(0.0f);
      if (!smooth_normal_in_after(v, corner_faces, normal)) return false;
      patch.normals.emplace_back(v, normal);
    }
    return true;
  }

  // v's smooth normal from the drawn faces around it, found from its fan in `after`; 0 for a dead or non-finite v.
  bool smooth_normal_in_after(uint32_t v, std::vector<CornerFace>& corner_faces, glm::vec3& normal) {
    if (!after.alive(VertexId(v)) || !finite(after.position(VertexId(v)))) return true;
    if (!walk_fan(after, v)) return false;
    corner_faces.clear();
    for (HalfedgeId x : fan_walk) {
      const FaceId g = after.face(x);
      if (!g.valid() || g.is_boundary() || g.slot() >= after.face_capacity()) continue;
      auto [it, inserted] = drawn_after.try_emplace(g.slot());
      if (inserted && !draw(after, g.slot(), it->second)) return false;
      if (it->second.drawn()) corner_faces.push_back({g.slot(), &it->second});
    }
    normal = smooth_normal(v, corner_faces);
    return true;
  }

  // Edges, and the boundary list when a boundary edge is among them (before or after).
  void rewrite_edges() {
    for (uint32_t e : dirty_edges) rewrite_edge(e);
    if (patch.boundary_changed) {
      patch.boundary_edges = state.boundary_edges;
      for (uint32_t e : patch.boundary_edges) patch.boundary_segments.push_back(slot_edge(after, EdgeId(e)));
    }
  }

  void rewrite_edge(uint32_t e) {
    SlotCounts& counts = state.counts;
    const EdgeSegment old_segment = e < before.edge_capacity() ? slot_edge(before, EdgeId(e)) : kHiddenSegment;
    const EdgeSegment segment = e < after.edge_capacity() ? slot_edge(after, EdgeId(e)) : kHiddenSegment;
    if (before.alive(EdgeId(e))) --(hidden(old_segment) ? counts.skipped_edges : counts.edges);
    if (after.alive(EdgeId(e))) ++(hidden(segment) ? counts.skipped_edges : counts.edges);  // live: drawn or skipped
    const bool was = !hidden(old_segment) && (old_segment.flags & kEdgeBoundaryFlag);
    const bool is = !hidden(segment) && (segment.flags & kEdgeBoundaryFlag);
    if (was || is) patch.boundary_changed = true;
    if (was && !is) std::erase(state.boundary_edges, e);
    if (is && !was) {
      std::vector<uint32_t>& list = state.boundary_edges;
      list.insert(std::lower_bound(list.begin(), list.end(), e), e);
    }
    if (e < after.edge_capacity()) patch.edges.emplace_back(e, segment);
  }

  // Arrows of the changed halfedges and of the halfedges of the faces drawn.
  void rewrite_arrows(const ChangedIds& changed) {
    dirty_arrows.insert(dirty_arrows.end(), changed.halfedges.begin(), changed.halfedges.end());
    sort_unique(dirty_arrows);
    for (uint32_t h : dirty_arrows) {
      if (h < after.halfedge_capacity()) patch.arrows.emplace_back(h, slot_arrow(after, HalfedgeId(h)));
    }
  }
};

// plan_update for either kind of `before` (a copy of the mesh, or the state read through the edit's patch).
template <class Before>
std::optional<SlotPatch> plan(const Before& before, const HalfedgeMesh& after, std::span<const ElementRef> changed,
                              SlotState& state, bool arrows, std::string& why) {
  Planner<Before> p{before, after, state, why, arrows};
  const ChangedIds ids = sorted_changes(changed);
  if (!p.find_dirty_faces(ids) || !p.find_dirty_edges(ids)) return std::nullopt;
  state.references.apply(before, after, ids.halfedges, ids.edges);
  p.patch.vertex_capacity = after.vertex_capacity();
  p.patch.halfedge_capacity = after.halfedge_capacity();
  p.patch.edge_capacity = after.edge_capacity();
  p.patch.face_capacity = after.face_capacity();
  if (!p.redraw_faces(ids)) return std::nullopt;
  p.rewrite_points(ids);
  if (!p.rewrite_smooth_normals()) return std::nullopt;
  p.rewrite_edges();
  if (arrows) p.rewrite_arrows(ids);
  p.patch.counts = state.counts;
  p.patch.bounds = state.bounds;
  return std::move(p.patch);
}

}  // namespace

SlotState slot_state(const HalfedgeMesh& mesh, const SlotGeometry& g) {
  SlotState s;
  s.references = MeshReferences::count(mesh);
  s.counts = g.counts;
  s.boundary_edges = g.boundary_edges;
  s.bounds = g.bounds;
  if (!g.extra_faces.empty()) {
    s.extra_first.assign(g.face_normals.size(), kInvalidIndex);
    for (size_t i = g.extra_faces.size(); i-- > 0;) s.extra_first[g.extra_faces[i]] = uint32_t(i);
  }
  return s;
}

std::optional<SlotPatch> plan_update(const HalfedgeMesh& before, const HalfedgeMesh& after,
                                     std::span<const ElementRef> changed, SlotState& state, bool arrows,
                                     std::string& why) {
  return plan(before, after, changed, state, arrows, why);
}

std::optional<SlotPatch> plan_update(const StateBefore& before, const HalfedgeMesh& after,
                                     std::span<const ElementRef> changed, SlotState& state, bool arrows,
                                     std::string& why) {
  return plan(before, after, changed, state, arrows, why);
}

void apply_patch(SlotGeometry& g, std::vector<EdgeSegment>* arrows, const SlotPatch& patch) {
  g.positions.resize(patch.vertex_capacity, glm::vec3(0.0f));
  g.smooth_normals.resize(patch.vertex_capacity, glm::vec3(0.0f));
  g.points.resize(patch.vertex_capacity, kHiddenPoint);
  g.triangles.resize(size_t(patch.face_capacity) * 3, 0u);
  g.face_normals.resize(patch.face_capacity, glm::vec4(0.0f));
  g.edges.resize(patch.edge_capacity, kHiddenSegment);
  for (const auto& [v, point] : patch.points) {
    g.points[v] = point;
    g.positions[v] = point.position;
  }
  for (const auto& [v, normal] : patch.normals) g.smooth_normals[v] = normal;
  for (const FacePatch& f : patch.faces) {
    std::copy(f.triangle.begin(), f.triangle.end(), g.triangles.begin() + 3 * long(f.face));
    g.face_normals[f.face] = f.normal;
  }
  for (const auto& [e, segment] : patch.edges) g.edges[e] = segment;
  for (const auto& [i, triangle] : patch.extra_triangles) {
    std::copy(triangle.begin(), triangle.end(), g.extra_triangles.begin() + 3 * long(i));
  }
  if (patch.boundary_changed) g.boundary_edges = patch.boundary_edges;
  g.counts = patch.counts;
  g.bounds = patch.bounds;
  if (arrows != nullptr) {
    arrows->resize(size_t(patch.halfedge_capacity) * 3, kHiddenSegment);
    for (const auto& [h, three] : patch.arrows) std::copy(three.begin(), three.end(), arrows->begin() + 3 * long(h));
  }
}

}  // namespace meshedit
