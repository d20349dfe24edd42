// Loop subdivision in a few passes over the flat arrays: the same mesh, id for id and bit for bit, as the
// teaching path (loop_subdivide_by_phases: split every original edge in id order, flip the new edges that join an
// old and a new vertex, move the vertices), computed without replaying it.
//
// Why this is possible (and what the equality test in tests/core/loop_fast_test.cpp holds us to):
// - Ids. split() appends its elements in a documented order (mesh_ops.h), so the k-th live original edge, with bb
//   boundary edges before it, gets vertex V0 + k, edges E0 + 3k - bb (ea, ec, ed), faces F0 + 2k - bb (g0, g1) and
//   halfedges H0 + 6k - 2bb (n0..n5); a boundary split makes no ed, g1, n4, n5.
// - Locality. A split rewires only the two triangles beside its edge, and a flip only the two triangles beside the
//   flipped edge, which lie inside one original triangle. So each original triangle T ends up as a function of
//   T alone: the order (by edge id) in which its three edges were split and, for each, whether T's halfedge was
//   split()'s h0 (T's side gets n0, n2, n3, g0) or h1 (n1, n4, n5, g1). Those three splits and the one flip are
//   replayed once on slot numbers for each of the 6 x 8 cases (loop_triangle_cases.h), and pass_triangles writes
//   each triangle from its case.
// - The one flip per triangle is the crossing edge of T's first split (it joins the first midpoint to the corner
//   opposite); the other two crossing edges join two midpoints. Flips never move a vertex's halfedge here: old
//   vertices point at original or n0 halfedges and midpoints at n1, never at a crossing halfedge.
// - An old vertex's halfedge x changes only when x is split()'s h0 of its edge (it becomes that split's n0).
// - Positions use loop_rules.h with the same neighbour order, so they are the same doubles.
// - Rows (triangle_rows.h). pass_triangles takes the triangles in row order (the mesh's rows, or live faces in id
//   order when it has none) and the four faces T becomes take four consecutive rows, at 4 x T's row, so each
//   level's rows follow the surface more closely and the next level reads its neighbours close together.
// Passes write disjoint elements per index (parallel_for), and each reads only what no pass running at the same
// time writes: vertex points go to a temporary array until every vertex has read its neighbours.
#include <algorithm>
#include <memory>
#include <vector>

#include "core/finite.h"
#include "core/loop_rules.h"
#include "core/loop_subdivision.h"
#include "core/loop_triangle_cases.h"
#include "core/memory_hints.h"
#include "core/mesh_storage.h"
#include "core/parallel_for.h"
#include "core/ring_walks.h"

namespace meshedit {
namespace {

constexpr uint32_t kBoundaryFlag = 0x80000000u;

// Where the split of one original edge puts its new elements.
struct EdgePlan {
  uint32_t rank = 0;             // k: live original edges before this one
  uint32_t boundary_before = 0;  // bb, with kBoundaryFlag set when this edge is on a boundary
  uint32_t face_side = 0;        // split()'s h0: e.halfedge, or its twin when e.halfedge lies on a boundary loop
  bool boundary() const { return (boundary_before & kBoundaryFlag) != 0; }
  uint32_t bb() const { return boundary_before & ~kBoundaryFlag; }
};

struct Level {
  uint32_t v0, h0, e0, f0;  // capacities before the level
  MeshStorage::View m;
  MeshArray<EdgePlan>& plan;  // by original edge id (dead edges: unused)

  uint32_t vertex_of(uint32_t e) const { return v0 + plan[e].rank; }
  uint32_t first_edge(uint32_t e) const { return e0 + 3 * plan[e].rank - plan[e].bb(); }
  uint32_t first_face(uint32_t e) const { return f0 + 2 * plan[e].rank - plan[e].bb(); }
  uint32_t first_halfedge(uint32_t e) const { return h0 + 6 * plan[e].rank - 2 * plan[e].bb(); }
  uint32_t face_side(uint32_t e) const { return plan[e].face_side; }
};

// A boundary edge and its face side: split()'s h0, the edge's halfedge unless that lies on a boundary loop.
struct BoundarySide {
  uint32_t edge, face_side;
};

// Every boundary edge once, by edge id, found by walking the boundary loops (few halfedges; none on a closed mesh).
std::vector<BoundarySide> boundary_sides(const Level& L, const HalfedgeMesh& mesh) {
  std::vector<BoundarySide> sides;
  for (FaceId loop : mesh.boundaries()) {
    mesh.for_each_face_halfedge(loop, [&](HalfedgeId b) {
      const uint32_t e = L.m.h[b.index].edge.index, h = L.m.edge_halfedge[e].index;
      sides.push_back({e, L.m.h[h].face.is_boundary() ? L.m.h[h].twin.index : h});
    });
  }
  std::sort(sides.begin(), sides.end(), [](const BoundarySide& a, const BoundarySide& b) { return a.edge < b.edge; });
  // An edge with both sides on loops was seen twice.
  sides.erase(std::unique(sides.begin(), sides.end(),
                          [](const BoundarySide& a, const BoundarySide& b) { return a.edge == b.edge; }),
              sides.end());
  return sides;
}

// Ranks the live edges and counts boundary edges before each, reading no halfedge but the boundary loops'. With no
// dead edge an edge's rank is its id and this is one pass; otherwise a first pass counts each chunk's live edges.
void plan_edges(Level& L, int threads, const HalfedgeMesh& mesh, uint32_t& live_edges, uint32_t& boundary_edges) {
  resize_for_overwrite(L.plan, L.e0);  // every entry is written below, dead edges' too
  const std::vector<BoundarySide> sides = boundary_sides(L, mesh);
  const size_t chunks = chunk_count(threads, L.e0);
  std::vector<uint32_t> live_before(chunks + 1, 0);
  const bool any_dead = mesh.num_edges() != L.e0;
  if (!any_dead) {
    for (size_t c = 0; c <= chunks; ++c) live_before[c] = uint32_t(chunk_begin(c, chunks, L.e0));
  } else {
    parallel_chunks(threads, L.e0, [&](size_t chunk, size_t begin, size_t end) {
      uint32_t n = 0;
      for (size_t e = begin; e < end; ++e) n += (*L.m.edge_alive)[e] ? 1 : 0;
      live_before[chunk + 1] = n;
    });
    for (size_t c = 0; c < chunks; ++c) live_before[c + 1] += live_before[c];
  }
  parallel_chunks(threads, L.e0, [&](size_t chunk, size_t begin, size_t end) {
    EdgePlan* plan = L.plan.data();
    const HalfedgeId* edge_halfedge = L.m.edge_halfedge;
    const AliveFlags& alive = *L.m.edge_alive;
    auto side =
        std::lower_bound(sides.begin(), sides.end(), begin, [](const BoundarySide& s, size_t e) { return s.edge < e; });
    uint32_t n = live_before[chunk], before = uint32_t(side - sides.begin());
    size_t next_boundary = side != sides.end() ? side->edge : end;
    for (size_t e = begin; e < end; ++e) {
      if (any_dead && !alive[e]) {
        plan[e] = EdgePlan{};
      } else if (e == next_boundary) {
        plan[e] = EdgePlan{n++, before++ | kBoundaryFlag, side->face_side};
        ++side;
        next_boundary = side != sides.end() ? side->edge : end;
      } else {
        plan[e] = EdgePlan{n++, before, edge_halfedge[e].index};
      }
    }
  });
  live_edges = live_before[chunks];
  boundary_edges = uint32_t(sides.size());
}

// Pass 1: each old vertex's new position (into `points`, read by nobody else) and its new halfedge. The rings are
// walked several at a time (ring_walks.h); each lane sums its vertex's neighbours in walk order.
class VertexPoints {
 public:
  VertexPoints(Level& level, LoopWeights weights, MeshArray<glm::dvec3>& points)
      : L_(level), weight_(weights), points_(points) {}

  void begin(unsigned lane, uint32_t) { sums_[lane] = Sum{}; }

  void neighbour(unsigned lane, uint32_t q_vertex, bool rim) {
    Sum& s = sums_[lane];
    const glm::dvec3& q = L_.m.position[q_vertex];
    s.neighbours += q;
    ++s.valence;
    if (rim) {
      if (s.rim_count < 2) s.rim[s.rim_count] = q;
      ++s.rim_count;
    }
  }

  void end(unsigned lane, uint32_t v, uint32_t start) {
    const Sum& s = sums_[lane];
    const glm::dvec3& p = L_.m.position[v];
    if (s.rim_count == 0) {
      points_[v] = loop_rules::interior_vertex(p, s.neighbours, s.valence, weight_(s.valence));
    } else if (s.rim_count == 2) {
      points_[v] = loop_rules::boundary_vertex(p, s.rim[0], s.rim[1]);
    } else {
      points_[v] = p;
    }
    const uint32_t e = L_.m.h[start].edge.index;
    if (L_.face_side(e) == start) L_.m.vertex_halfedge[v] = HalfedgeId(L_.first_halfedge(e));  // becomes n0
  }

 private:
  struct Sum {
    glm::dvec3 neighbours{0.0}, rim[2];
    uint32_t valence = 0, rim_count = 0;
  };
  Level& L_;
  loop_rules::ValenceWeights weight_;
  MeshArray<glm::dvec3>& points_;
  Sum sums_[ring_walks::kLanes];
};

void pass_vertices(Level& L, LoopWeights weights, int threads, MeshArray<glm::dvec3>& points) {
  parallel_for(threads, L.v0, [&](size_t begin, size_t end) {
    VertexPoints visitor(L, weights, points);
    ring_walks::walk_rings(L.m, begin, end, visitor);
  });
}

// Pass 2: per original edge, its midpoint vertex, the new edges' halfedges, and on a boundary edge the loop's side
// (n1 inserted after h1).
void pass_edges(Level& L, int threads) {
  parallel_for(threads, L.e0, [&](size_t begin, size_t end) {
    const MeshStorage::View& m = L.m;
    for (size_t e = begin; e < end; ++e) {
      // h0 -> twin, next -> their nexts -> the opposite corners' positions: a chain of cache misses, started
      // for later edges one link per stage (dead edges skipped). The last two stages follow h1.next, which on a
      // boundary edge is a loop halfedge whose next another edge rewrites meanwhile: they skip boundary edges.
      const auto live = [&](size_t g) { return g < end && (*m.edge_alive)[g]; };
      const auto interior = [&](size_t g) { return live(g) && !L.plan[g].boundary(); };
      if (live(e + 32)) memory_hints::prefetch_record(&m.h[L.face_side(uint32_t(e + 32))]);
      if (live(e + 24)) {
        const HalfedgeRecord& h0 = m.h[L.face_side(uint32_t(e + 24))];
        memory_hints::prefetch_record(&m.h[h0.twin.index]);
        memory_hints::prefetch_record(&m.h[h0.next.index]);
      }
      if (live(e + 16)) {
        const HalfedgeRecord& h0 = m.h[L.face_side(uint32_t(e + 16))];
        const HalfedgeRecord& h1 = m.h[h0.twin.index];
        memory_hints::prefetch_record(&m.h[h1.next.index]);
        memory_hints::prefetch_record(&m.h[m.h[h0.next.index].next.index]);
        memory_hints::prefetch(&m.position[h0.vertex.index]);
        memory_hints::prefetch(&m.position[h1.vertex.index]);
      }
      if (interior(e + 8)) {
        const HalfedgeRecord& h0 = m.h[L.face_side(uint32_t(e + 8))];
        const HalfedgeRecord& h1 = m.h[h0.twin.index];
        memory_hints::prefetch_record(&m.h[m.h[h1.next.index].next.index]);
        memory_hints::prefetch(&m.position[m.h[m.h[h0.next.index].next.index].vertex.index]);
      }
      if (interior(e + 4)) {
        const HalfedgeRecord& h1 = m.h[m.h[L.face_side(uint32_t(e + 4))].twin.index];
        memory_hints::prefetch(&m.position[m.h[m.h[h1.next.index].next.index].vertex.index]);
      }
      if (!(*m.edge_alive)[e]) continue;
      const auto edge = uint32_t(e);
      const bool boundary = L.plan[e].boundary();
      const uint32_t h0 = L.face_side(edge), h1 = m.h[h0].twin.index;
      const uint32_t mid = L.vertex_of(edge), ea = L.first_edge(edge), n0 = L.first_halfedge(edge);
      const glm::dvec3& a = m.position[m.h[h0].vertex.index];
      const glm::dvec3& b = m.position[m.h[h1].vertex.index];
      if (boundary) {
        m.position[mid] = loop_rules::boundary_edge(a, b);
      } else {
        const glm::dvec3& c = m.position[m.h[m.h[m.h[h0].next.index].next.index].vertex.index];
        const glm::dvec3& d = m.position[m.h[m.h[m.h[h1].next.index].next.index].vertex.index];
        m.position[mid] = loop_rules::interior_edge(a, b, c, d);
      }
      m.vertex_halfedge[mid] = HalfedgeId(n0 + 1);
      m.edge_halfedge[ea] = HalfedgeId(n0);                         // ea: n0 a->m, n1 m->a
      m.edge_halfedge[ea + 1] = HalfedgeId(n0 + 2);                 // ec: n2 m->c, n3 c->m
      if (!boundary) m.edge_halfedge[ea + 2] = HalfedgeId(n0 + 4);  // ed: n4 m->d, n5 d->m
      if (boundary) {  // the loop's side: n1 after h1 (the face side's halfedges are written by pass_triangles)
        const uint32_t n1 = n0 + 1;
        m.h[n1] = HalfedgeRecord{m.h[h1].next, HalfedgeId(n0), VertexId(mid), EdgeId(ea), m.h[h1].face};
        m.h[h1].next = HalfedgeId(n1);
      }
    }
  });
}

// The order pass_triangles takes the triangles in, and where it puts their faces: the triangle in row r (its
// face_at_row[r]) puts its four faces in rows 4r to 4r + 3. The next level reads next_face_at_row (when there is
// one), the mesh keeps rows (after the last level). Neighbours on the surface come close in the rows, so the
// triangles that share an edge are mostly written one soon after the other.
struct RowOrder {
  const uint32_t* face_at_row;  // this level's input: every live face once
  size_t count;                 // its live faces
  uint32_t* next_face_at_row;   // its output's, or null
  TriangleRow* rows;            // the output's rows, or null
};

// Every id one original triangle's rewrite needs: its 12 halfedges (x0..x2, then o, p, q per side), its 4 faces, its
// 6 vertices (corners, then the midpoints of its sides), each new halfedge's twin and edge, and its case.
struct TriangleIds {
  uint32_t id[12], face_id[4], vertex_id[6], twin_id[9], edge_id[9];
  const loop_cases::TriangleCase* c;
};

// The ids of the triangle of face f: its three sides' splits, as the plan places them.
inline void triangle_ids(const Level& L, const loop_cases::TriangleCase* cases, size_t f, TriangleIds& t) {
  const MeshStorage::View& m = L.m;
  uint32_t rank[3];
  unsigned sides = 0;
  t.id[0] = m.face_halfedge[f].index;
  t.id[1] = m.h[t.id[0]].next.index;
  t.id[2] = m.h[t.id[1]].next.index;
  t.face_id[0] = uint32_t(f);
  for (uint32_t i = 0; i < 3; ++i) {
    const HalfedgeRecord& x = m.h[t.id[i]];
    const uint32_t e = x.edge.index;
    const EdgePlan& p = L.plan[e];
    const bool side_h0 = p.face_side == t.id[i];
    sides |= unsigned(side_h0) << i;
    rank[i] = p.rank;
    t.vertex_id[i] = x.vertex.index;
    t.vertex_id[3 + i] = L.vertex_of(e);
    const uint32_t n0 = L.first_halfedge(e), ea = L.first_edge(e);
    t.id[3 + i] = side_h0 ? n0 : n0 + 1;      // o: n0 or n1, on ea
    t.id[6 + i] = side_h0 ? n0 + 2 : n0 + 4;  // p: n2 or n4, on ec or ed
    t.id[9 + i] = t.id[6 + i] + 1;            // q: n3 or n5
    t.twin_id[i] = side_h0 ? n0 + 1 : n0;
    t.twin_id[3 + i] = t.id[9 + i];
    t.twin_id[6 + i] = t.id[6 + i];
    t.edge_id[i] = ea;
    t.edge_id[3 + i] = t.edge_id[6 + i] = ea + (side_h0 ? 1 : 2);
    t.face_id[1 + i] = L.first_face(e) + (side_h0 ? 0 : 1);
  }
  t.c = &cases[loop_cases::case_index(loop_cases::order_code(rank[0], rank[1], rank[2]), sides)];
}

// Writes the triangle's 12 halfedges and its 4 faces' halfedges from its case.
inline void write_triangle(const MeshStorage::View& m, const TriangleIds& t) {
  const loop_cases::TriangleCase& c = *t.c;
  for (uint32_t s = 0; s < 3; ++s) {  // the original halfedges keep their twin and edge
    HalfedgeRecord& r = m.h[t.id[s]];
    r.next = HalfedgeId(t.id[c.next[s]]);
    r.face = FaceId::face(t.face_id[c.face[s]]);
    r.vertex = VertexId(t.vertex_id[c.vertex[s]]);
  }
  for (uint32_t s = 3; s < 12; ++s) {  // new halfedges: every field, in one store each
    m.h[t.id[s]] =
        HalfedgeRecord{HalfedgeId(t.id[c.next[s]]), HalfedgeId(t.twin_id[s - 3]), VertexId(t.vertex_id[c.vertex[s]]),
                       EdgeId(t.edge_id[s - 3]), FaceId::face(t.face_id[c.face[s]])};
  }
  for (uint32_t g = 0; g < 4; ++g) m.face_halfedge[t.face_id[g]] = HalfedgeId(t.id[c.face_halfedge[g]]);
}

// The triangle in row `row` puts its four faces in rows 4 row .. 4 row + 3 of the next level's order or the rows.
inline void write_rows(const RowOrder& order, size_t row, const TriangleIds& t) {
  const size_t first_row = 4 * row;
  if (order.next_face_at_row) {
    for (uint32_t g = 0; g < 4; ++g) order.next_face_at_row[first_row + g] = t.face_id[g];
  }
  if (order.rows) {  // one 64-byte line, written past the caches: the rows are read only after Loop
    const loop_cases::TriangleCase& c = *t.c;
    for (uint32_t g = 0; g < 4; ++g) {
      const TriangleRow row_of_face{{VertexId(t.vertex_id[c.corner[g][0]]), VertexId(t.vertex_id[c.corner[g][1]]),
                                     VertexId(t.vertex_id[c.corner[g][2]])},
                                    FaceId::face(t.face_id[g])};
      memory_hints::stream_store(&order.rows[first_row + g], &row_of_face);
    }
  }
}

// Pass 3: every original triangle's 12 halfedges (next, face, vertex) and its 4 faces' halfedges, from its case,
// and the four faces' places in the row order.
void pass_triangles(Level& L, int threads, const RowOrder& order) {
  const loop_cases::TriangleCase* cases = loop_cases::triangle_cases();  // made before the threads start
  parallel_for(threads, order.count, [&](size_t begin, size_t end) {
    const MeshStorage::View& m = L.m;
    const uint32_t* face_at = order.face_at_row;
    for (size_t row = begin; row < end; ++row) {
      // The chain row -> face -> x0 -> x1 -> x2 and each side's plan are dependent cache misses: start them for
      // later rows now, one link per stage.
      if (row + 32 < end) memory_hints::prefetch(&m.face_halfedge[face_at[row + 32]]);
      if (row + 24 < end) memory_hints::prefetch_record(&m.h[m.face_halfedge[face_at[row + 24]].index]);
      if (row + 16 < end) {
        const HalfedgeRecord& x0 = m.h[m.face_halfedge[face_at[row + 16]].index];
        memory_hints::prefetch_record(&m.h[x0.next.index]);
        memory_hints::prefetch(&L.plan[x0.edge.index]);
      }
      if (row + 8 < end) {
        const HalfedgeRecord& x1 = m.h[m.h[m.face_halfedge[face_at[row + 8]].index].next.index];
        memory_hints::prefetch_record(&m.h[x1.next.index]);
        memory_hints::prefetch(&L.plan[x1.edge.index]);
      }
      if (row + 4 < end) {
        const HalfedgeRecord& x2 = m.h[m.h[m.h[m.face_halfedge[face_at[row + 4]].index].next.index].next.index];
        memory_hints::prefetch(&L.plan[x2.edge.index]);
      }
      if (row + 4 < end) {  // the new halfedges (six per side, written three by each triangle) and faces ahead
        uint32_t x = m.face_halfedge[face_at[row + 4]].index;
        for (int i = 0; i < 3; ++i, x = m.h[x].next.index) {
          const uint32_t e = m.h[x].edge.index, n0 = L.first_halfedge(e);
          memory_hints::prefetch_for_write(&m.h[n0]);
          memory_hints::prefetch_for_write(&m.h[n0 + 5]);
          memory_hints::prefetch_for_write(&m.face_halfedge[L.first_face(e)]);
        }
      }
      TriangleIds t;
      triangle_ids(L, cases, face_at[row], t);
      write_triangle(m, t);
      write_rows(order, row, t);
    }
    memory_hints::stream_fence();
  });
}

// Per-level scratch arrays, sized once for the last level so no level faults in fresh pages for them.
struct Scratch {
  MeshArray<EdgePlan> plan;
  MeshArray<glm::dvec3> points;
  MeshArray<uint32_t> face_at_row, next_face_at_row;  // RowOrder's, for the level's input and output
};

// The first level's face_at_row: the faces in the order of the mesh's rows when it has them, else in id order.
void first_row_order(const HalfedgeMesh& mesh, const TriangleRows* rows, MeshArray<uint32_t>& face_at_row) {
  resize_for_overwrite(face_at_row, mesh.num_faces());  // every entry written below
  size_t r = 0;
  if (rows) {
    for (const TriangleRow& row : *rows) face_at_row[r++] = row.face.slot();
    return;
  }
  for (FaceId f : mesh.faces()) face_at_row[r++] = f.slot();
}

// Subdivides once. With `check_finite`, also returns whether every live position of the result is finite (with huge
// coordinates a weighted sum can overflow); otherwise true.
// `rows`: where the last level writes its output's rows (null before the last level).
bool subdivide_level(HalfedgeMesh& mesh, LoopWeights weights, int threads, Scratch& scratch, bool check_finite,
                     TriangleRows* rows) {
  Level L{mesh.vertex_capacity(), mesh.halfedge_capacity(), mesh.edge_capacity(),
          mesh.face_capacity(),   MeshStorage::view(mesh),  scratch.plan};
  uint32_t live_edges = 0, boundary_edges = 0;
  plan_edges(L, threads, mesh, live_edges, boundary_edges);
  MeshStorage::grow(mesh, L.v0 + live_edges, L.h0 + 6 * live_edges - 2 * boundary_edges,
                    L.e0 + 3 * live_edges - boundary_edges, L.f0 + 2 * live_edges - boundary_edges);
  L.m = MeshStorage::view(mesh);

  MeshArray<glm::dvec3>& points = scratch.points;
  resize_for_overwrite(points, L.v0);  // written for live vertices, read only for them
  pass_vertices(L, weights, threads, points);
  pass_edges(L, threads);
  const size_t input_faces = mesh.num_faces() / 4;  // grow() counted the output: four faces for each
  if (rows) {
    resize_for_overwrite(*rows, mesh.num_faces());  // every row written
  } else {
    resize_for_overwrite(scratch.next_face_at_row, mesh.num_faces());  // every entry written
  }
  pass_triangles(L, threads,
                 RowOrder{scratch.face_at_row.data(), input_faces, rows ? nullptr : scratch.next_face_at_row.data(),
                          rows ? rows->data() : nullptr});
  if (!rows) scratch.face_at_row.swap(scratch.next_face_at_row);
  const size_t vertices = check_finite ? mesh.vertex_capacity() : L.v0;
  std::vector<uint8_t> chunk_finite(chunk_count(threads, vertices), 1);
  parallel_chunks(threads, vertices, [&](size_t chunk, size_t begin, size_t end) {
    bool all_finite = true;
    for (size_t v = begin; v < end; ++v) {
      if (!(*L.m.vertex_alive)[v]) continue;
      if (v < L.v0) L.m.position[v] = points[v];
      if (check_finite) all_finite = all_finite && finite(L.m.position[v]);
    }
    chunk_finite[chunk] = all_finite;
  });
  MeshStorage::touch(mesh);
  return std::all_of(chunk_finite.begin(), chunk_finite.end(), [](uint8_t f) { return f != 0; });
}

}  // namespace

Check loop_subdivide(HalfedgeMesh& mesh, LoopWeights weights, int levels, int threads) {
  if (levels <= 0) return Check::yes();
  // Checked once: a mesh this accepts subdivides into one it accepts again (valid, triangles, no two faces with
  // the same corners), so later levels need no check.
  if (Check ok = can_loop_subdivide(mesh, threads); !ok) return ok;
  // Room for the last level up front, so no level copies the arrays again. Per level, capacities grow by at most
  // E vertices, 6E halfedges, 3E edges and 2E faces (fewer on a boundary), and the live counts become
  // E' = 2E + 3F, F' = 4F.
  size_t vertices = mesh.vertex_capacity(), halfedges = mesh.halfedge_capacity(), edges = mesh.edge_capacity(),
         faces = mesh.face_capacity(), live_edges = mesh.num_edges(), live_faces = mesh.num_faces();
  Scratch scratch;
  // The rows the mesh has (if any) order the first level (the first write drops them); the last level's output gets
  // new ones.
  first_row_order(mesh, mesh.triangle_rows(), scratch.face_at_row);
  for (int i = 0; i < levels; ++i) {
    if (i + 1 == levels) {
      scratch.plan.reserve(edges);
      scratch.points.reserve(vertices);
      scratch.face_at_row.reserve(live_faces);  // the two swap at each level but the last
      scratch.next_face_at_row.reserve(live_faces);
    }
    vertices += live_edges;
    halfedges += 6 * live_edges;
    edges += 3 * live_edges;
    faces += 2 * live_edges;
    const size_t next_edges = 2 * live_edges + 3 * live_faces;
    live_faces *= 4;
    live_edges = next_edges;
  }
  MeshStorage::reserve_total(mesh, vertices, halfedges, edges, faces);
  auto rows = std::make_shared<TriangleRows>();
  rows->reserve(live_faces);  // every allocation before the first level, so running out of memory changes nothing
  bool positions_finite = true;
  for (int i = 0; i < levels; ++i) {
    const bool last = i + 1 == levels;
    positions_finite = subdivide_level(mesh, weights, threads, scratch, last, last ? rows.get() : nullptr);
  }
  // Accepted input, so the result is valid and all triangles, unless a position overflowed; its connectivity is the
  // rows' either way.
  if (positions_finite) MeshStorage::vouch_valid_triangles(mesh);
  MeshStorage::set_triangle_rows(mesh, std::move(rows));
  return Check::yes();
}

}  // namespace meshedit
