// The subdivision schemes' phases, one call each (see subdivision_phases.h).
#include "core/subdivision_phases.h"

#include <algorithm>
#include <cstddef>

namespace meshedit {
namespace {

Check loop_levels(HalfedgeMesh& mesh, LoopWeights weights, int levels, int threads) {
  return loop_subdivide(mesh, weights, levels, threads);
}
Check catmull_clark_levels(HalfedgeMesh& mesh, LoopWeights, int levels, int) {
  return catmull_clark_subdivide(mesh, levels);
}
Check linear_levels(HalfedgeMesh& mesh, LoopWeights, int levels, int) { return linear_subdivide(mesh, levels); }

struct SchemeRow {
  SubdivisionScheme scheme;
  const char* name;
  const char* title;
  int phases;
  std::string labels[5];  // by phase, 1-based; labels[0] unused
  // The whole scheme in one call (subdivide): the weights are Loop's only, the threads Loop's only.
  Check (*subdivide)(HalfedgeMesh& mesh, LoopWeights weights, int levels, int threads);
};

// One row per scheme: its name, its phases' labels and its one call, made when the program starts.
const SchemeRow kSchemes[] = {
    {SubdivisionScheme::Loop,
     "loop",
     "Loop",
     4,
     {"", "Loop 1/4: compute new positions", "Loop 2/4: split every original edge",
      "Loop 3/4: flip new edges joining an old and a new vertex", "Loop 4/4: move every vertex to its new position"},
     loop_levels},
    {SubdivisionScheme::CatmullClark,
     "catmull-clark",
     "Catmull-Clark",
     3,
     {"", "Catmull-Clark 1/3: compute face, edge and vertex points",
      "Catmull-Clark 2/3: split every face into quads (nothing moves yet)",
      "Catmull-Clark 3/3: move every vertex to its point"},
     catmull_clark_levels},
    {SubdivisionScheme::Linear,
     "linear",
     "Linear",
     2,
     {"", "Linear 1/2: compute edge midpoints and face centres",
      "Linear 2/2: split every face (triangles in four, other faces into quads)"},
     linear_levels},
};

const SchemeRow& row(SubdivisionScheme scheme) {
  return *std::find_if(std::begin(kSchemes), std::end(kSchemes),
                       [&](const SchemeRow& r) { return r.scheme == scheme; });
}

size_t count_placed(const std::vector<uint32_t>& ids) {
  return size_t(std::count_if(ids.begin(), ids.end(), [](uint32_t id) { return id != RefineLayout::kNone; }));
}

std::string points(size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace

const char* scheme_name(SubdivisionScheme scheme) { return row(scheme).name; }

const char* scheme_title(SubdivisionScheme scheme) { return row(scheme).title; }

std::optional<SubdivisionScheme> scheme_named(std::string_view name) {
  for (const SchemeRow& r : kSchemes) {
    if (name == r.name) return r.scheme;
  }
  return std::nullopt;
}

const char* scheme_names() {
  static const std::string kNames = [] {
    std::string text;
    const size_t n = std::size(kSchemes);
    for (size_t i = 0; i < n; ++i) {
      text += std::string(i == 0 ? "" : i + 1 == n ? " or " : ", ") + "\"" + kSchemes[i].name + "\"";
    }
    return text;
  }();
  return kNames.c_str();
}

int phase_count(SubdivisionScheme scheme) { return row(scheme).phases; }

Check subdivide(HalfedgeMesh& mesh, SubdivisionScheme scheme, LoopWeights weights, int levels, int threads) {
  return row(scheme).subdivide(mesh, weights, levels, threads);
}

const std::string& phase_label(SubdivisionScheme scheme, int phase) {
  return row(scheme).labels[std::clamp(phase, 1, phase_count(scheme))];
}

SubdivisionPhases::SubdivisionPhases(SubdivisionScheme scheme, LoopWeights weights)
    : scheme_(scheme), weights_(weights) {}

SubdivisionPhases::Capacities SubdivisionPhases::capacities_of(const HalfedgeMesh& mesh) {
  return {mesh.vertex_capacity(), mesh.halfedge_capacity(), mesh.edge_capacity(), mesh.face_capacity()};
}

Check SubdivisionPhases::run_next(HalfedgeMesh& mesh) {
  const int phase = next_phase_;
  if (phase > 1 && capacities_of(mesh) != left_) {
    restart();
    return Check::no(std::string("the mesh changed after ") + scheme_title(scheme_) + " phase " +
                     std::to_string(phase - 1) + "; the phases start again at phase 1");
  }
  if (phase == 1) {
    Check check;
    switch (scheme_) {
      case SubdivisionScheme::Loop: {
        OpResult<LoopState> computed = loop_compute_positions(mesh, weights_);
        check = std::move(computed.check);
        loop_ = std::move(computed.value);
        break;
      }
      case SubdivisionScheme::CatmullClark: {
        OpResult<CatmullClarkState> computed = catmull_clark_compute_points(mesh);
        check = std::move(computed.check);
        catmull_clark_ = std::move(computed.value);
        break;
      }
      case SubdivisionScheme::Linear: {
        OpResult<LinearState> computed = linear_compute_points(mesh);
        check = std::move(computed.check);
        linear_ = std::move(computed.value);
        break;
      }
    }
    if (!check) {
      restart();
      return check;
    }
    computed_from_ = {mesh.num_vertices(), mesh.num_edges(), mesh.num_faces()};
  } else if (scheme_ == SubdivisionScheme::Loop) {
    if (phase == 2) loop_split_edges(mesh, loop_);
    if (phase == 3) loop_flip_edges(mesh, loop_);
    if (phase == 4) loop_commit_positions(mesh, loop_);
  } else if (scheme_ == SubdivisionScheme::CatmullClark) {
    if (phase == 2) catmull_clark_refine(mesh, catmull_clark_);
    if (phase == 3) catmull_clark_commit_positions(mesh, catmull_clark_);
  } else {
    linear_refine(mesh, linear_);
  }
  if (phase == phase_count(scheme_)) {
    restart();
  } else {
    next_phase_ = phase + 1;
    left_ = capacities_of(mesh);
  }
  return Check::yes();
}

void SubdivisionPhases::restart() {
  next_phase_ = 1;
  loop_ = LoopState{};
  catmull_clark_ = CatmullClarkState{};
  linear_ = LinearState{};
}

const LoopState* SubdivisionPhases::loop_state() const {
  return computed() && scheme_ == SubdivisionScheme::Loop ? &loop_ : nullptr;
}

const CatmullClarkState* SubdivisionPhases::catmull_clark_state() const {
  return computed() && scheme_ == SubdivisionScheme::CatmullClark ? &catmull_clark_ : nullptr;
}

const LinearState* SubdivisionPhases::linear_state() const {
  return computed() && scheme_ == SubdivisionScheme::Linear ? &linear_ : nullptr;
}

std::string SubdivisionPhases::computed_summary() const {
  if (!computed()) return "";
  const MeshCounts& n = computed_from_;
  switch (scheme_) {
    case SubdivisionScheme::Loop: return points(n.vertices, "vertex position") + ", " + points(n.edges, "edge point");
    case SubdivisionScheme::CatmullClark:
      return points(n.faces, "face point") + ", " + points(n.edges, "edge point") + ", " +
             points(n.vertices, "vertex point");
    case SubdivisionScheme::Linear:
      return points(n.edges, "edge midpoint") + ", " + points(count_placed(linear_.layout.face_vertex), "face centre");
  }
  return "";
}

}  // namespace meshedit
