// The three subdivision schemes as phases to step through, one call per phase: what the window's Subdivide menu,
// a lesson's headless answers and Lua's mesh:subdivision_phases all run.
//
//   Loop           4 phases (loop_subdivision.h): compute positions, split every original edge, flip new edges
//                  joining an old and a new vertex, move every vertex;
//   Catmull-Clark  3 phases (catmull_clark.h): compute face, edge and vertex points, split every face into quads,
//                  move every vertex;
//   Linear         2 phases (linear_subdivision.h): compute midpoints and centres, split every face.
// Phase 1 only computes: it reads the mesh and changes nothing. Each later phase changes the mesh. After the last
// phase the next is phase 1 again. One table in subdivision_phases.cpp lists the schemes: the names the shell, Lua
// and the answers files take, the phases' labels, and the one-call subdivision (subdivide) the shell and the
// headless answers run.
//
// Invariants:
// - The phases in turn give the mesh the scheme's one-call subdivision gives, id for id (the core's tests hold
//   the by-phases calls to the one-call ones).
// - A refused phase 1 (what the scheme's can_* refuses) changes nothing and leaves the stepper at phase 1.
// - The phases after the first need the mesh the previous phase left: a caller whose mesh may have changed in between
//   (an undo, another edit) calls restart() first, as only the caller knows what "the same mesh" means to it (a
//   document's generation and version, a Lua mesh's version). As a last guard, a later phase refuses (and restarts)
//   a mesh whose id capacities differ from those the previous phase left, rather than read past what phase 1
//   computed.
// - The labels are made when the program starts: asking for one allocates nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/catmull_clark.h"
#include "core/check.h"
#include "core/halfedge_mesh.h"
#include "core/linear_subdivision.h"
#include "core/loop_subdivision.h"

namespace meshedit {

enum class SubdivisionScheme { Loop, CatmullClark, Linear };

// "loop", "catmull-clark", "linear": the names the shell, Lua and the answers files use.
const char* scheme_name(SubdivisionScheme scheme);
std::optional<SubdivisionScheme> scheme_named(std::string_view name);
// "Loop", "Catmull-Clark", "Linear": the scheme in a sentence.
const char* scheme_title(SubdivisionScheme scheme);
// "\"loop\", \"catmull-clark\" or \"linear\"": for the messages that refuse another name.
const char* scheme_names();
int phase_count(SubdivisionScheme scheme);
// The scheme's whole subdivision, `levels` times, in one call: loop_subdivide (with `weights`, on `threads`),
// catmull_clark_subdivide or linear_subdivide.
Check subdivide(HalfedgeMesh& mesh, SubdivisionScheme scheme, LoopWeights weights = LoopWeights::Course, int levels = 1,
                int threads = 1);
// "Catmull-Clark 2/3: split every face into quads (nothing moves yet)"; phase in 1..phase_count.
const std::string& phase_label(SubdivisionScheme scheme, int phase);

class SubdivisionPhases {
 public:
  explicit SubdivisionPhases(SubdivisionScheme scheme = SubdivisionScheme::Loop,
                             LoopWeights weights = LoopWeights::Course);

  SubdivisionScheme scheme() const { return scheme_; }
  int next_phase() const { return next_phase_; }
  const std::string& next_label() const { return phase_label(scheme_, next_phase_); }
  // Whether phase 1 has run and a later phase is still to come (the computed points are then at hand).
  bool computed() const { return next_phase_ > 1; }

  // Runs the next phase on `mesh`. Phase 1 may refuse (see above); a later phase only a mesh of other capacities.
  Check run_next(HalfedgeMesh& mesh);
  // Back to phase 1, the computed points dropped.
  void restart();

  // What phase 1 computed, while computed() and the scheme is that one; else nullptr.
  const LoopState* loop_state() const;
  const CatmullClarkState* catmull_clark_state() const;
  const LinearState* linear_state() const;
  // "8 vertex points, 12 edge points": what phase 1 computed, for a status line; "" before phase 1.
  std::string computed_summary() const;

 private:
  SubdivisionScheme scheme_;
  LoopWeights weights_;
  int next_phase_ = 1;
  struct MeshCounts {
    size_t vertices = 0, edges = 0, faces = 0;
  };
  MeshCounts computed_from_;  // the live elements of the mesh phase 1 read
  struct Capacities {
    uint32_t vertices = 0, halfedges = 0, edges = 0, faces = 0;
    bool operator==(const Capacities&) const = default;
  };
  static Capacities capacities_of(const HalfedgeMesh& mesh);
  Capacities left_;  // the id capacities of the mesh the last phase left
  LoopState loop_;
  CatmullClarkState catmull_clark_;
  LinearState linear_;
};

}  // namespace meshedit
