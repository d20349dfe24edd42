// The repair steps of mesh_repair.h on a working copy of the polygons: faces are dropped by flag (so a face's index
// stays its original number), vertices are only appended (so an original vertex keeps its number) until step 6
// renumbers both. Messages that name new vertices, and every change's spots, are made after that renumbering (a
// cut's message and spots read the vertices at its corners then, from the working copy's final corners).
//
// Map of this file (each part starts at its `// ---- name` banner):
//   working copy                          EdgeUse, Renumbering, Work (the polygons being repaired), edge_uses,
//                                         for_each_edge, goes_up, corner_of, find_root
//   steps 1 and 2: dropped faces          drop_bad_faces, drop_repeated_faces
//   step 3: edges of three or more faces  detach_extra_faces
//   step 4: orientation and cuts          orient_components (the walks: face_links, walk_component,
//                                         reverse_minority), then cut_edges (split_cut_pieces, say_cut)
//   step 5: bow-ties                      split_bowties
//   step 6 and the output                 finish: the final numbers, the repaired polygons
//   repair_polygons                       the steps in order
#include "core/mesh_repair.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <numeric>
#include <span>

#include <glm/geometric.hpp>

#include "core/triangulate.h"

namespace meshedit {
namespace {

// ---- working copy ----------------------------------------------------------------------------------

constexpr uint32_t kNone = UINT32_MAX;

// One face's use of an undirected edge: the edge (min, max) as a key, the face, and the corner it leaves from.
struct EdgeUse {
  uint64_t key;
  uint32_t face;
  uint32_t corner;
  bool operator<(const EdgeUse& o) const { return key != o.key ? key < o.key : face < o.face; }
};

// Renumbering of step 6: vertex -> its number in the repaired polygons (kNone: dropped).
using FinalNumbers = std::vector<uint32_t>;
using Message = std::function<std::string(const FinalNumbers&)>;
// The renumbering of vertices and of faces (face -> its index among the kept faces, kNone: dropped).
struct Renumbering {
  FinalNumbers vertices, faces;
};
using SpotMaker = std::function<RepairSpots(const Renumbering&)>;

// The numbers that survive, renumbered, in the order given.
std::vector<uint32_t> renumbered(const FinalNumbers& final, const std::vector<uint32_t>& numbers) {
  std::vector<uint32_t> out;
  for (uint32_t x : numbers) {
    if (final[x] != kNone) out.push_back(final[x]);
  }
  return out;
}

// Spots of the given working vertices and faces (either list may be empty).
SpotMaker spots_of(std::vector<uint32_t> vertices, std::vector<uint32_t> faces) {
  return [vertices = std::move(vertices), faces = std::move(faces)](const Renumbering& r) {
    return RepairSpots{renumbered(r.vertices, vertices), renumbered(r.faces, faces)};
  };
}

struct Work {
  std::vector<glm::dvec3> positions;
  std::vector<uint32_t> indices;
  std::vector<uint32_t> offsets;
  std::vector<uint8_t> kept;  // per face
  size_t original_vertices = 0;
  std::vector<Message> messages;  // formatted once the final numbers are known
  std::vector<SpotMaker> spots;   // spots[i] for messages[i]
  RepairReport report;

  size_t num_faces() const { return offsets.size() - 1; }
  uint32_t size(uint32_t f) const { return offsets[f + 1] - offsets[f]; }
  uint32_t& at(uint32_t f, uint32_t c) { return indices[offsets[f] + c]; }
  uint32_t at(uint32_t f, uint32_t c) const { return indices[offsets[f] + c]; }
  uint32_t copy_vertex(uint32_t v) {
    positions.push_back(positions[v]);
    return static_cast<uint32_t>(positions.size() - 1);
  }
  void say(std::string text, SpotMaker where) {
    messages.push_back([text = std::move(text)](const FinalNumbers&) { return text; });
    spots.push_back(std::move(where));
  }
  void say(Message text, SpotMaker where) {
    messages.push_back(std::move(text));
    spots.push_back(std::move(where));
  }
  // "vertex 12" for an original vertex, "new vertex 41" (its final number) for a copy.
  Message vertex_name(uint32_t v) const {
    const bool original = v < original_vertices;
    return [v, original](const FinalNumbers& final) {
      return original ? "vertex " + std::to_string(v) : "new vertex " + std::to_string(final[v]);
    };
  }
};

std::vector<uint32_t> sorted_copy(std::vector<uint32_t> numbers) {
  std::sort(numbers.begin(), numbers.end());
  return numbers;
}

uint64_t edge_key(uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

// Every kept face's edge uses, sorted by edge key, then face: bucketed by the edge's lower vertex (linear), then each
// small bucket sorted.
std::vector<EdgeUse> edge_uses(const Work& w) {
  std::vector<uint32_t> start(w.positions.size() + 1, 0);
  for (uint32_t f = 0; f < w.num_faces(); ++f) {
    if (!w.kept[f]) continue;
    const uint32_t n = w.size(f);
    for (uint32_t c = 0; c < n; ++c) ++start[std::min(w.at(f, c), w.at(f, (c + 1) % n)) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<EdgeUse> uses(start.back());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (uint32_t f = 0; f < w.num_faces(); ++f) {
    if (!w.kept[f]) continue;
    const uint32_t n = w.size(f);
    for (uint32_t c = 0; c < n; ++c) {
      const uint32_t a = w.at(f, c), b = w.at(f, (c + 1) % n);
      uses[fill[std::min(a, b)]++] = {edge_key(a, b), f, c};
    }
  }
  for (size_t v = 0; v + 1 < start.size(); ++v) std::sort(uses.begin() + start[v], uses.begin() + start[v + 1]);
  return uses;
}

// Calls visit(first, last) for each run of uses of one edge.
template <class Visit>
void for_each_edge(const std::vector<EdgeUse>& uses, Visit&& visit) {
  for (size_t i = 0; i < uses.size();) {
    size_t j = i + 1;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    visit(i, j);
    i = j;
  }
}

// Whether face f's use of its edge at `corner` goes from the lower vertex number to the higher.
bool goes_up(const Work& w, const EdgeUse& u) {
  return w.at(u.face, u.corner) < w.at(u.face, (u.corner + 1) % w.size(u.face));
}

// The index in w.indices of face f's corner at vertex v (v is one of its corners).
uint32_t corner_of(const Work& w, uint32_t f, uint32_t v) {
  uint32_t i = w.offsets[f];
  while (w.indices[i] != v) ++i;
  return i;
}

// Union-find: the root of x's set, halving the path on the way.
uint32_t find_root(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// ---- steps 1 and 2: dropped faces ------------------------------------------------------------------

void drop_bad_faces(Work& w) {
  std::vector<uint32_t> sorted;
  std::vector<glm::dvec3> corners;
  for (uint32_t f = 0; f < w.num_faces(); ++f) {
    const uint32_t n = w.size(f);
    const std::string face = "face " + std::to_string(f);  // short: no allocation
    std::string why;
    for (uint32_t c = 0; c < n && why.empty(); ++c) {
      if (w.at(f, c) >= w.original_vertices) {
        why = face + " uses vertex " + std::to_string(w.at(f, c)) + ", but there are only " +
              std::to_string(w.original_vertices) + ": dropped";
      }
    }
    if (why.empty() && n < 3) why = face + " has " + std::to_string(n) + " corners: dropped";
    if (why.empty()) {
      sorted.assign(w.indices.begin() + w.offsets[f], w.indices.begin() + w.offsets[f + 1]);
      std::sort(sorted.begin(), sorted.end());
      const auto repeat = std::adjacent_find(sorted.begin(), sorted.end());
      if (repeat != sorted.end()) why = face + " repeats vertex " + std::to_string(*repeat) + ": dropped";
    }
    if (why.empty()) {
      corners.clear();
      double perimeter = 0;
      for (uint32_t c = 0; c < n; ++c) {
        corners.push_back(w.positions[w.at(f, c)]);
        perimeter += glm::length(w.positions[w.at(f, (c + 1) % n)] - w.positions[w.at(f, c)]);
      }
      if (glm::length(newell_normal(corners)) <= 1e-12 * perimeter * perimeter) {
        why = face + " has zero area: dropped";
      }
    }
    if (why.empty()) continue;
    w.kept[f] = 0;
    ++w.report.dropped_bad_faces;
    std::vector<uint32_t> in_range;  // the corners that are vertices (each once, in corner order)
    for (uint32_t c = 0; c < n; ++c) {
      const uint32_t v = w.at(f, c);
      if (v < w.original_vertices && std::find(in_range.begin(), in_range.end(), v) == in_range.end()) {
        in_range.push_back(v);
      }
    }
    w.say(std::move(why), spots_of(std::move(in_range), {}));
  }
}

// A face's corners sorted (the same set of corners in any order or direction gives the same list).
void sorted_corners(const Work& w, uint32_t f, std::vector<uint32_t>& out) {
  out.assign(w.indices.begin() + w.offsets[f], w.indices.begin() + w.offsets[f + 1]);
  std::sort(out.begin(), out.end());
}

void drop_repeated_faces(Work& w) {
  // Faces ordered by a hash of their sorted corners, then by number: repeats are neighbours, the first one first.
  std::vector<std::pair<uint64_t, uint32_t>> keyed;
  keyed.reserve(w.num_faces());
  std::vector<uint32_t> corners, other;
  for (uint32_t f = 0; f < w.num_faces(); ++f) {
    if (!w.kept[f]) continue;
    sorted_corners(w, f, corners);
    uint64_t h = 1469598103934665603ull;
    for (uint32_t x : corners) h = (h ^ x) * 1099511628211ull;
    keyed.emplace_back(h, f);
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::pair<uint32_t, uint32_t>> repeats;  // (face, the earlier face it repeats)
  for (size_t i = 0; i < keyed.size();) {
    size_t j = i + 1;
    while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
    for (size_t k = i + 1; k < j; ++k) {  // rare: only faces whose hashes collide or repeat
      sorted_corners(w, keyed[k].second, corners);
      for (size_t e = i; e < k; ++e) {
        sorted_corners(w, keyed[e].second, other);
        if (other == corners) {
          repeats.emplace_back(keyed[k].second, keyed[e].second);
          break;
        }
      }
    }
    i = j;
  }
  std::sort(repeats.begin(), repeats.end());
  for (const auto& [f, earlier] : repeats) {
    w.kept[f] = 0;
    ++w.report.dropped_repeated_faces;
    w.say("face " + std::to_string(f) + " repeated face " + std::to_string(earlier) + ": dropped",
          spots_of({}, {earlier}));
  }
}

// ---- step 3: edges of three or more faces ----------------------------------------------------------

// Returns whether any face was detached (so `uses` no longer describes the faces).
bool detach_extra_faces(Work& w, const std::vector<EdgeUse>& uses) {
  const size_t before = w.report.detached_faces;
  for_each_edge(uses, [&](size_t first, size_t last) {
    if (last - first < 3) return;
    const uint32_t a = uint32_t(uses[first].key >> 32), b = uint32_t(uses[first].key);
    // Uses still on this edge (an earlier detachment may have moved a face off it).
    std::vector<EdgeUse> on;
    for (size_t i = first; i < last; ++i) {
      const EdgeUse& u = uses[i];
      if (edge_key(w.at(u.face, u.corner), w.at(u.face, (u.corner + 1) % w.size(u.face))) == u.key) on.push_back(u);
    }
    if (on.size() < 3) return;
    size_t partner = 1;
    for (size_t i = 1; i < on.size(); ++i) {
      if (goes_up(w, on[i]) != goes_up(w, on[0])) {
        partner = i;
        break;
      }
    }
    std::vector<size_t> sharing;
    for (const EdgeUse& u : on) sharing.push_back(u.face);
    for (size_t i = 1; i < on.size(); ++i) {
      if (i == partner) continue;
      const EdgeUse& u = on[i];
      const uint32_t next = (u.corner + 1) % w.size(u.face);
      const uint32_t from = w.at(u.face, u.corner), to = w.at(u.face, next);
      const uint32_t from_copy = w.copy_vertex(from), to_copy = w.copy_vertex(to);
      w.at(u.face, u.corner) = from_copy;
      w.at(u.face, next) = to_copy;
      ++w.report.detached_faces;
      const Message va = w.vertex_name(a), vb = w.vertex_name(b);
      const std::string faces = number_list(sharing);
      const uint32_t face = u.face;
      w.say(
          [=](const FinalNumbers& final) {
            return "the edge between " + va(final) + " and " + vb(final) + " had faces " + faces + ": face " +
                   std::to_string(face) + " detached (its corners there are now new vertices " +
                   std::to_string(final[from_copy]) + " and " + std::to_string(final[to_copy]) + ")";
          },
          spots_of({from_copy, to_copy}, {face}));
    }
  });
  return w.report.detached_faces != before;
}

// ---- step 4: orientation and cuts -----------------------------------------------------------------

// Two faces on an edge of exactly two faces (a link of the walk), with whether they use the edge the same way.
struct Link {
  uint64_t key;
  uint32_t f, g;  // f < g
  uint8_t same;
};

// Each face's links: adjacent[start[f] .. start[f + 1]) holds (the other face, the link's index).
struct FaceLinks {
  std::vector<Link> links;
  std::vector<uint32_t> start;
  std::vector<std::pair<uint32_t, uint32_t>> adjacent;
};

FaceLinks face_links(const Work& w, const std::vector<EdgeUse>& uses) {
  FaceLinks l;
  for_each_edge(uses, [&](size_t first, size_t last) {
    if (last - first != 2 || uses[first].face == uses[first + 1].face) return;
    l.links.push_back({uses[first].key, uses[first].face, uses[first + 1].face,
                       goes_up(w, uses[first]) == goes_up(w, uses[first + 1])});
  });
  l.start.assign(w.num_faces() + 1, 0);
  for (const Link& k : l.links) ++l.start[k.f + 1], ++l.start[k.g + 1];
  std::partial_sum(l.start.begin(), l.start.end(), l.start.begin());
  l.adjacent.resize(l.start.back());
  std::vector<uint32_t> fill(l.start.begin(), l.start.end() - 1);
  for (uint32_t i = 0; i < l.links.size(); ++i) {
    l.adjacent[fill[l.links[i].f]++] = {l.links[i].g, i};
    l.adjacent[fill[l.links[i].g]++] = {l.links[i].f, i};
  }
  return l;
}

// The walk's state: per face, whether it was reached and whether it is to be flipped; per link, whether it is cut.
struct Walk {
  std::vector<uint8_t> seen, flip, cut;
  std::vector<uint32_t> cuts;  // the cut links, in the order the walk met them
};

// Breadth-first from `seed` over the links, filling `component` in walking order. A face's orientation is fixed
// when it is first reached; a link whose faces the fixed orientations make use the edge the same way is cut.
void walk_component(const FaceLinks& l, uint32_t seed, Walk& walk, std::vector<uint32_t>& component) {
  component.assign(1, seed);
  walk.seen[seed] = 1;
  for (size_t k = 0; k < component.size(); ++k) {
    const uint32_t f = component[k];
    for (uint32_t i = l.start[f]; i < l.start[f + 1]; ++i) {
      const auto [g, link] = l.adjacent[i];
      const uint8_t wanted = walk.flip[f] ^ l.links[link].same;
      if (!walk.seen[g]) {
        walk.seen[g] = 1;
        walk.flip[g] = wanted;
        component.push_back(g);
      } else if (walk.flip[g] != wanted && !walk.cut[link]) {
        walk.cut[link] = 1;
        walk.cuts.push_back(link);
      }
    }
  }
}

// Reverses the faces of `component` whose orientation fewer of them have, and says so.
void reverse_minority(Work& w, const std::vector<uint32_t>& component, const std::vector<uint8_t>& flip) {
  size_t flipped = 0;
  for (uint32_t f : component) flipped += flip[f];
  if (flipped == 0) return;
  const uint8_t reverse = 2 * flipped > component.size() ? 0 : 1;  // the majority keeps its orientation
  std::vector<size_t> reversed;
  std::vector<uint32_t> reversed_faces;
  uint32_t reference = kNone;
  for (uint32_t f : component) {
    if (flip[f] == reverse) {
      reversed.push_back(f);
      reversed_faces.push_back(f);
      std::reverse(w.indices.begin() + w.offsets[f] + 1, w.indices.begin() + w.offsets[f + 1]);
    } else {
      reference = std::min(reference, f);
    }
  }
  w.report.reversed_faces += reversed.size();
  w.say(std::string(reversed.size() == 1 ? "face " : "faces ") + number_list(reversed) +
            " reversed to agree with face " + std::to_string(reference),
        spots_of({}, sorted_copy(reversed_faces)));
}

// `uses` must describe the faces as they are; reversing faces leaves their undirected edges as they were. Returns
// the links the walks cut, in the order they met them.
std::vector<Link> orient_components(Work& w, const std::vector<EdgeUse>& uses) {
  const FaceLinks l = face_links(w, uses);
  Walk walk{std::vector<uint8_t>(w.num_faces(), 0),
            std::vector<uint8_t>(w.num_faces(), 0),
            std::vector<uint8_t>(l.links.size(), 0),
            {}};
  std::vector<uint32_t> component;
  for (uint32_t seed = 0; seed < w.num_faces(); ++seed) {
    if (!w.kept[seed] || walk.seen[seed]) continue;
    walk_component(l, seed, walk, component);
    reverse_minority(w, component, walk.flip);
  }
  std::vector<Link> cuts;
  for (uint32_t link : walk.cuts) cuts.push_back(l.links[link]);
  return cuts;
}

// One corner of a vertex at a cut's end: its index in w.indices, and its face.
struct EndCorner {
  uint32_t vertex, corner, face;
  bool operator<(const EndCorner& o) const { return vertex != o.vertex ? vertex < o.vertex : corner < o.corner; }
};

// The new vertex of each of v's corners (`corners`, in face order) once the cut edges no longer join them: its
// corners fall into fans (joined through edges of exactly two faces) and each fan into pieces (joined through those
// edges that are not cut). In each fan the piece with the lowest face keeps v, each other piece gets a new vertex.
// The new numbers are appended to `moves` as (corner, vertex), so that other vertices' pieces are found from the
// corners as they were.
void split_cut_pieces(Work& w, uint32_t v, std::span<const EndCorner> corners, const std::vector<uint64_t>& cut_keys,
                      std::vector<std::pair<uint32_t, uint32_t>>& moves) {
  const auto n = static_cast<uint32_t>(corners.size());
  std::vector<std::pair<uint32_t, uint32_t>> ends;  // (the vertex at the other end of an edge at v, local corner)
  for (uint32_t k = 0; k < n; ++k) {
    const uint32_t f = corners[k].face, begin = w.offsets[f], size = w.size(f), c = corners[k].corner - begin;
    ends.emplace_back(w.indices[begin + (c + 1) % size], k);
    ends.emplace_back(w.indices[begin + (c + size - 1) % size], k);
  }
  std::sort(ends.begin(), ends.end());
  std::vector<uint32_t> fan(n), piece(n);
  std::iota(fan.begin(), fan.end(), 0u);
  std::iota(piece.begin(), piece.end(), 0u);
  for (size_t i = 0; i + 1 < ends.size(); ++i) {
    if (ends[i].first != ends[i + 1].first) continue;  // at most two: no edge has three faces any more
    const uint32_t a = ends[i].second, b = ends[i + 1].second;
    fan[find_root(fan, a)] = find_root(fan, b);
    if (!std::binary_search(cut_keys.begin(), cut_keys.end(), edge_key(v, ends[i].first))) {
      piece[find_root(piece, a)] = find_root(piece, b);
    }
  }
  std::vector<uint32_t> vertex_of(n, kNone);  // per piece root
  std::vector<uint8_t> fan_kept(n, 0);        // per fan root: whether a piece of it keeps v
  for (uint32_t k = 0; k < n; ++k) {
    uint32_t& vertex = vertex_of[find_root(piece, k)];
    if (vertex == kNone) {
      uint8_t& keeper = fan_kept[find_root(fan, k)];
      vertex = keeper ? w.copy_vertex(v) : v;
      keeper = 1;
    }
    if (vertex != v) moves.emplace_back(corners[k].corner, vertex);
  }
}

// The corners at a cut's ends (indices in w.indices): face f's at a and at b, then face g's.
struct CutCorners {
  uint32_t fa, fb, ga, gb;
};

// Says that `cut` was cut. The vertices at its corners are read when the message is made, after every step, so
// they are the repaired polygons' (a later bow-tie split may have moved one of them again).
void say_cut(Work& w, const Link& cut, const CutCorners& at) {
  const Message va = w.vertex_name(uint32_t(cut.key >> 32)), vb = w.vertex_name(uint32_t(cut.key));
  const std::vector<uint32_t>* indices = &w.indices;  // Work outlives its messages
  const size_t original = w.original_vertices;
  const auto corner_name = [indices, original](const FinalNumbers& final, uint32_t corner) {
    const uint32_t v = (*indices)[corner];
    return v < original ? "vertex " + std::to_string(v) : "new vertex " + std::to_string(final[v]);
  };
  const std::string f = std::to_string(cut.f), g = std::to_string(cut.g);
  w.say(
      [=](const FinalNumbers& final) {
        return "the edge between " + va(final) + " and " + vb(final) + " was cut: faces " + f + " and " + g +
               " disagree on its direction; it is now between " + corner_name(final, at.fa) + " and " +
               corner_name(final, at.fb) + " in face " + f + ", and between " + corner_name(final, at.ga) + " and " +
               corner_name(final, at.gb) + " in face " + g;
      },
      [indices, at, cut](const Renumbering& r) {
        RepairSpots spots;
        for (uint32_t corner : {at.fa, at.fb, at.ga, at.gb}) spots.vertices.push_back(r.vertices[(*indices)[corner]]);
        spots.faces = {r.faces[cut.f], r.faces[cut.g]};
        return spots;
      });
}

// Cuts the edges the walks could not orient (`cuts`): the corners at their ends are split into pieces
// (split_cut_pieces), so that each cut edge's two faces no longer share either end. Returns whether anything was
// cut (so the edge uses no longer describe the faces).
bool cut_edges(Work& w, const std::vector<Link>& cuts) {
  if (cuts.empty()) return false;
  std::vector<uint64_t> cut_keys;
  std::vector<CutCorners> at;
  std::vector<uint8_t> at_cut(w.positions.size(), 0);
  for (const Link& c : cuts) {
    const uint32_t a = uint32_t(c.key >> 32), b = uint32_t(c.key);
    cut_keys.push_back(c.key);
    at.push_back({corner_of(w, c.f, a), corner_of(w, c.f, b), corner_of(w, c.g, a), corner_of(w, c.g, b)});
    at_cut[a] = at_cut[b] = 1;
  }
  std::sort(cut_keys.begin(), cut_keys.end());
  std::vector<EndCorner> corners;  // every corner at a cut's end, by vertex, then in face order
  for (uint32_t f = 0; f < w.num_faces(); ++f) {
    if (!w.kept[f]) continue;
    for (uint32_t i = w.offsets[f]; i < w.offsets[f + 1]; ++i) {
      if (at_cut[w.indices[i]]) corners.push_back({w.indices[i], i, f});
    }
  }
  std::sort(corners.begin(), corners.end());
  std::vector<std::pair<uint32_t, uint32_t>> moves;
  for (size_t i = 0; i < corners.size();) {
    size_t j = i + 1;
    while (j < corners.size() && corners[j].vertex == corners[i].vertex) ++j;
    split_cut_pieces(w, corners[i].vertex, std::span(corners).subspan(i, j - i), cut_keys, moves);
    i = j;
  }
  for (const auto& [corner, vertex] : moves) w.indices[corner] = vertex;
  w.report.cut_edges += cuts.size();
  for (size_t k = 0; k < cuts.size(); ++k) say_cut(w, cuts[k], at[k]);
  return true;
}

// ---- step 5: bow-ties ------------------------------------------------------------------------------

// `uses` gives each face's undirected edges as they are (its corner numbers may be stale after orient_components).
void split_bowties(Work& w, const std::vector<EdgeUse>& uses) {
  std::vector<uint32_t> parent(w.indices.size());
  std::iota(parent.begin(), parent.end(), 0u);
  // v is a corner of the face: the edge's key names two of them.
  const auto corner_at = [&](const EdgeUse& u, uint32_t v) { return corner_of(w, u.face, v); };
  for_each_edge(uses, [&](size_t first, size_t last) {
    if (last - first != 2) return;
    for (uint32_t v : {uint32_t(uses[first].key >> 32), uint32_t(uses[first].key)}) {
      parent[find_root(parent, corner_at(uses[first], v))] = find_root(parent, corner_at(uses[first + 1], v));
    }
  });
  // Corners of each vertex, in face order.
  const size_t vertices = w.positions.size();
  std::vector<uint32_t> start(vertices + 1, 0);
  std::vector<uint32_t> face_of(w.indices.size(), kNone);
  for (uint32_t f = 0; f < w.num_faces(); ++f) {
    if (!w.kept[f]) continue;
    for (uint32_t i = w.offsets[f]; i < w.offsets[f + 1]; ++i) ++start[w.indices[i] + 1], face_of[i] = f;
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<uint32_t> corners(start.back());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (uint32_t i = 0; i < w.indices.size(); ++i) {
    if (face_of[i] != kNone) corners[fill[w.indices[i]]++] = i;
  }
  std::vector<uint32_t> roots;
  for (uint32_t v = 0; v < vertices; ++v) {
    roots.clear();
    for (uint32_t k = start[v]; k < start[v + 1]; ++k) {
      const uint32_t r = find_root(parent, corners[k]);
      if (std::find(roots.begin(), roots.end(), r) == roots.end()) roots.push_back(r);
    }
    if (roots.size() < 2) continue;
    ++w.report.split_vertices;
    std::vector<uint32_t> copies;
    std::vector<std::vector<size_t>> moved(roots.size());
    for (size_t r = 1; r < roots.size(); ++r) copies.push_back(w.copy_vertex(v));
    for (uint32_t k = start[v]; k < start[v + 1]; ++k) {
      const size_t r = size_t(std::find(roots.begin(), roots.end(), find_root(parent, corners[k])) - roots.begin());
      if (r == 0) continue;
      w.indices[corners[k]] = copies[r - 1];
      moved[r].push_back(face_of[corners[k]]);
    }
    const Message name = w.vertex_name(v);
    const bool original = v < w.original_vertices;
    std::vector<uint32_t> spot_vertices{v}, spot_faces;
    spot_vertices.insert(spot_vertices.end(), copies.begin(), copies.end());
    for (size_t r = 1; r < moved.size(); ++r) {
      for (size_t f : moved[r]) spot_faces.push_back(uint32_t(f));
    }
    w.say(
        [=](const FinalNumbers& final) {
          std::string text = name(final) + " was a bow-tie: split into " + std::to_string(original ? v : final[v]);
          for (size_t r = 0; r < copies.size(); ++r) {
            text += (r + 1 == copies.size() ? " and new vertex " : ", new vertex ") + std::to_string(final[copies[r]]);
          }
          if (copies.size() == 1)
            return text + " (" + (moved[1].size() == 1 ? "face " : "faces ") + number_list(moved[1]) + " moved)";
          text += " (";
          for (size_t r = 1; r < moved.size(); ++r) {
            text += (r > 1 ? "; " : "") + std::string(moved[r].size() == 1 ? "face " : "faces ") +
                    number_list(moved[r]) + " moved to " + std::to_string(final[copies[r - 1]]);
          }
          return text + ")";
        },
        spots_of(std::move(spot_vertices), sorted_copy(std::move(spot_faces))));
  }
}

// ---- step 6 and the output -------------------------------------------------------------------------

// Step 6 and the output: the final numbers of used vertices and of kept faces, and the repaired polygons.
PolygonMesh finish(Work& w, Renumbering& numbers) {
  FinalNumbers& final = numbers.vertices;
  std::vector<uint8_t> used(w.positions.size(), 0);
  for (uint32_t f = 0; f < w.num_faces(); ++f) {
    if (!w.kept[f]) continue;
    for (uint32_t i = w.offsets[f]; i < w.offsets[f + 1]; ++i) used[w.indices[i]] = 1;
  }
  PolygonMesh out;
  final.assign(w.positions.size(), kNone);
  std::vector<size_t> unused;
  for (uint32_t v = 0; v < w.positions.size(); ++v) {
    if (!used[v]) {
      if (v < w.original_vertices) unused.push_back(v);
      continue;
    }
    final[v] = out.add_vertex(w.positions[v]);
  }
  if (!unused.empty()) {
    w.report.dropped_vertices = unused.size();
    w.say(std::string(unused.size() == 1 ? "vertex " : "vertices ") + number_list(unused) +
              (unused.size() == 1 ? " was" : " were") + " used by no face: dropped",
          spots_of({}, {}));
  }
  out.indices.reserve(w.indices.size());
  out.face_offsets.reserve(w.num_faces() + 1);
  numbers.faces.assign(w.num_faces(), kNone);
  for (uint32_t f = 0; f < w.num_faces(); ++f) {
    if (!w.kept[f]) continue;
    numbers.faces[f] = static_cast<uint32_t>(out.face_offsets.size() - 1);
    for (uint32_t i = w.offsets[f]; i < w.offsets[f + 1]; ++i) out.indices.push_back(final[w.indices[i]]);
    out.face_offsets.push_back(static_cast<uint32_t>(out.indices.size()));
  }
  return out;
}

}  // namespace

// ---- repair_polygons -------------------------------------------------------------------------------

RepairResult repair_polygons(const PolygonMesh& polygons) {
  Work w;
  w.positions = polygons.positions;
  w.indices = polygons.indices;
  w.offsets = polygons.face_offsets;
  w.kept.assign(polygons.num_faces(), 1);
  w.original_vertices = polygons.num_vertices();
  drop_bad_faces(w);
  drop_repeated_faces(w);
  std::vector<EdgeUse> uses = edge_uses(w);
  if (detach_extra_faces(w, uses)) uses = edge_uses(w);
  if (cut_edges(w, orient_components(w, uses))) uses = edge_uses(w);
  split_bowties(w, uses);
  RepairResult result;
  Renumbering numbers;
  result.polygons = finish(w, numbers);
  result.report = std::move(w.report);
  result.report.changes.reserve(w.messages.size());
  for (const Message& m : w.messages) result.report.changes.push_back(m(numbers.vertices));
  result.report.spots.reserve(w.spots.size());
  for (const SpotMaker& s : w.spots) result.report.spots.push_back(s(numbers));
  return result;
}

}  // namespace meshedit
