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

template <class Before>
struct Planner {
  const Before& before;
  const HalfedgeMesh& after;
  SlotState& state;
  std::string& why;
  std::vector<HalfedgeId> walk;  // scratch

  bool fail(std::string reason) {
    why = std::move(reason);
    return false;
  }

  // The halfedges y of `before` with twin(y) == t (certified by the twin counts of `before`), into `out`.
  bool twins_of(uint32_t t, std::vector<uint32_t>& out) {
    out.clear();
    const auto test = [&](uint32_t y) { return before.alive(HalfedgeId(y)) && before.twin(HalfedgeId(y)).index == t; };
    if (t < before.halfedge_capacity()) consider(before.twin(HalfedgeId(t)).index, out, test);
    if (t < after.halfedge_capacity()) consider(after.twin(HalfedgeId(t)).index, out, test);
    const uint32_t expected = t < state.references.twin_refs.size() ? state.references.twin_refs[t] : 0;
    return out.size() == expected || fail("h" + std::to_string(t) + " is the twin of halfedges not found");
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
    if (found.size() != expected) return fail("h" + std::to_string(h) + " is the halfedge of edges not found");
    out.insert(out.end(), found.begin(), found.end());
    return true;
  }

  template <class Mesh>
  bool draw(const Mesh& mesh, uint32_t f, FaceDraw& d) {
    d = FaceDraw();
    walk.clear();
    if (f >= mesh.face_capacity()) return true;
    draw_face(mesh, FaceId::face(f), d, walk, nullptr, kMaxWalk);
    if (d.walk == FaceWalk::TooLong) return fail("f" + std::to_string(f) + " is longer than the walk limit");
    return true;
  }
};

// plan_update for either kind of `before` (a copy of the mesh, or the state read through the edit's patch).
template <class Before>
std::optional<SlotPatch> plan(const Before& before, const HalfedgeMesh& after, std::span<const ElementRef> changed,
                              SlotState& state, bool arrows, std::string& why);

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

namespace {

template <class Before>
std::optional<SlotPatch> plan(const Before& before, const HalfedgeMesh& after, std::span<const ElementRef> changed,
                              SlotState& state, bool arrows, std::string& why) {
  Planner<Before> p{before, after, state, why, {}};
  std::vector<uint32_t> cv, ch, ce, cf;
  for (const ElementRef& ref : changed) {
    if (!ref.valid()) continue;
    switch (ref.kind) {
      case ElementKind::Vertex: cv.push_back(ref.index); break;
      case ElementKind::Halfedge: ch.push_back(ref.index); break;
      case ElementKind::Edge: ce.push_back(ref.index); break;
      case ElementKind::Face: cf.push_back(ref.index); break;
      case ElementKind::Boundary: break;
    }
  }
  for (auto* ids : {&cv, &ch, &ce, &cf}) sort_unique(*ids);

  // Dirty faces and edges, from `before`'s pointers and counts (what did not change reads the same in both states).
  std::vector<uint32_t> df = cf, de = ce, around;  // around: halfedges leaving a changed vertex in `before`
  const auto add_face = [&](FaceId f) {
    if (f.valid() && !f.is_boundary()) df.push_back(f.slot());
  };
  for (uint32_t h : ch) {
    if (h < before.halfedge_capacity()) add_face(before.face(HalfedgeId(h)));
    if (h < after.halfedge_capacity()) add_face(after.face(HalfedgeId(h)));
  }
  std::vector<HalfedgeId> out;
  for (uint32_t u : cv) {
    if (u >= before.vertex_capacity()) continue;  // new: whatever leaves it in `after` is new or changed
    if (!fan(before, VertexId(u), state.references.outgoing[u], out)) {
      return p.fail("the fan of v" + std::to_string(u) + " does not hold every halfedge leaving it"), std::nullopt;
    }
    for (HalfedgeId x : out) {
      add_face(before.face(x));
      around.push_back(x.index);
    }
  }
  // Edges read their halfedge h and twin(h): those of the changed halfedges, and those ending at a changed vertex.
  std::vector<uint32_t> reach = ch, twins;
  reach.insert(reach.end(), around.begin(), around.end());
  sort_unique(reach);
  for (uint32_t h : reach) {
    if (h >= before.halfedge_capacity()) continue;  // new: the edges and twins pointing at it changed too
    if (!p.edges_of(h, de) || !p.twins_of(h, twins)) return std::nullopt;
    for (uint32_t y : twins) {
      if (!p.edges_of(y, de)) return std::nullopt;
    }
  }
  sort_unique(df);
  sort_unique(de);

  state.references.apply(before, after, ch, ce);

  SlotPatch patch;
  patch.vertex_capacity = after.vertex_capacity();
  patch.halfedge_capacity = after.halfedge_capacity();
  patch.edge_capacity = after.edge_capacity();
  patch.face_capacity = after.face_capacity();
  SlotCounts& counts = state.counts;

  // Faces: triangles and flat normals; their corners' smooth normals and their halfedges' arrows become dirty.
  std::unordered_map<uint32_t, FaceDraw> drawn_after;
  std::vector<uint32_t> dv = cv, dh;
  FaceDraw old_draw;
  for (uint32_t f : df) {
    FaceDraw& new_draw = drawn_after[f];
    if (!p.draw(before, f, old_draw)) return std::nullopt;
    if (arrows) for (HalfedgeId h : p.walk) dh.push_back(h.index);
    if (!p.draw(after, f, new_draw)) return std::nullopt;
    if (arrows) for (HalfedgeId h : p.walk) dh.push_back(h.index);
    dv.insert(dv.end(), old_draw.corners.begin(), old_draw.corners.end());
    dv.insert(dv.end(), new_draw.corners.begin(), new_draw.corners.end());
    if (before.alive(FaceId::face(f))) {
      if (old_draw.drawn()) counts.triangles -= old_draw.triangle_count();
      else --counts.skipped_faces;
    }
    if (after.alive(FaceId::face(f))) {
      if (new_draw.drawn()) counts.triangles += new_draw.triangle_count();
      else ++counts.skipped_faces;
    }
    // A polygon keeps its packed later triangles where they are only if it has as many as before.
    const size_t extra = new_draw.triangle_count() > 0 ? new_draw.triangle_count() - 1 : 0;
    const size_t old_extra = old_draw.triangle_count() > 0 ? old_draw.triangle_count() - 1 : 0;
    if (extra != old_extra) return p.fail("f" + std::to_string(f) + " has another number of triangles"), std::nullopt;
    for (size_t i = 0; i < extra; ++i) {
      const std::vector<uint32_t>& c = new_draw.corners;
      patch.extra_triangles.push_back({state.extra_first[f] + uint32_t(i), {c[0], c[i + 2], c[i + 3]}});
    }
    if (f >= after.face_capacity()) continue;
    FacePatch fp{f, {0, 0, 0}, flat_normal(new_draw.term)};
    if (new_draw.drawn()) fp.triangle = {new_draw.corners[0], new_draw.corners[1], new_draw.corners[2]};
    patch.faces.push_back(fp);
  }

  // Points (and positions) of the changed vertices.
  for (uint32_t v : cv) {
    if (v < before.vertex_capacity() && slot_point(before, VertexId(v)).vertex != kInvalidIndex) --counts.vertices;
    if (v >= after.vertex_capacity()) continue;
    const VertexPoint point = slot_point(after, VertexId(v));
    if (point.vertex != kInvalidIndex) {
      ++counts.vertices;
      state.bounds.add(after.position(VertexId(v)));
    }
    patch.points.emplace_back(v, point);
  }

  // Smooth normals: the drawn faces around each dirty vertex, found from its fan in `after`.
  sort_unique(dv);
  std::vector<CornerFace> corner_faces;
  for (uint32_t v : dv) {
    if (v >= after.vertex_capacity()) continue;
    glm::vec3 normal(0.0f);
    if (after.alive(VertexId(v)) && finite(after.position(VertexId(v)))) {
      if (!fan(after, VertexId(v), state.references.outgoing[v], out)) {
        return p.fail("the fan of v" + std::to_string(v) + " does not hold every halfedge leaving it"), std::nullopt;
      }
      corner_faces.clear();
      for (HalfedgeId x : out) {
        const FaceId g = after.face(x);
        if (!g.valid() || g.is_boundary() || g.slot() >= after.face_capacity()) continue;
        auto [it, inserted] = drawn_after.try_emplace(g.slot());
        if (inserted && !p.draw(after, g.slot(), it->second)) return std::nullopt;
        if (it->second.drawn()) corner_faces.push_back({g.slot(), &it->second});
      }
      normal = smooth_normal(v, corner_faces);
    }
    patch.normals.emplace_back(v, normal);
  }

  // Edges, and the boundary list when a boundary edge is among them (before or after).
  for (uint32_t e : de) {
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
  if (patch.boundary_changed) {
    patch.boundary_edges = state.boundary_edges;
    for (uint32_t e : patch.boundary_edges) patch.boundary_segments.push_back(slot_edge(after, EdgeId(e)));
  }

  if (arrows) {
    dh.insert(dh.end(), ch.begin(), ch.end());
    sort_unique(dh);
    for (uint32_t h : dh) {
      if (h < after.halfedge_capacity()) patch.arrows.emplace_back(h, slot_arrow(after, HalfedgeId(h)));
    }
  }
  patch.counts = counts;
  patch.bounds = state.bounds;
  return patch;
}

}  // namespace

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
