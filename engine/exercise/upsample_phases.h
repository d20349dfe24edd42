// Where the four phases of Loop subdivision begin in a recording of a student's upsample(mesh) (edit_recorder.h):
//
//   1. new positions computed   the positions of steps 1 and 2 live in the student's Lua tables: nothing is written
//                               to the mesh, so phase 1 is the state before the first write (replay position 0)
//   2. edges split              mesh:split / split_edge (one "split" operation each), or a split written by hand
//                               (mesh:new_*, then pointer writes)
//   3. new edges flipped        mesh:flip / flip_edge (one "flip" operation each), or a flip written by hand
//                               (pointer writes only)
//   4. positions committed      v.position = ... on a vertex that is not being made by a hand-written split
//
//   const UpsamplePhases phases = find_upsample_phases(report.mine.edits);
//   phases.span[3].first      // index of the first flip: replay position first + 1 shows it
//   phases.phase_at(k)        // the phase of write k (1-based, as the replay counts; 0 is phase 1)
//   phases.problems           // "phase 3 (new edges flipped) never started: no flip was recorded", ...
//
// Invariants:
// - Pure: reads the edits only (no mesh, no Lua); any list of edits gives an answer, never an exception.
// - Every edit gets exactly one phase: the kinds above, or Other for operations Loop subdivision does not use
//   (collapse, loop_subdivide, restore, undo, redo).
// - A pointer write belongs to a hand-written split when its script line (`where`) writes mostly near the
//   creations of new elements (within kNearCreation edits, no operation or position commit between), else to a
//   hand-written flip. Code that splits and flips through one shared helper line is taken for splits.
// - span[p].first is the index of phase p's first edit; phases that never started, or that started out of order
//   or came back after a later phase began, are named in `problems` (at most kMaxProblems lines), with the write
//   number (1-based) and the script line.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/edit_log.h"

namespace meshedit {

enum class UpsamplePhase : uint8_t { Other = 0, Compute = 1, Split = 2, Flip = 3, Commit = 4 };
inline constexpr int kUpsamplePhaseCount = 4;

// "new positions computed", "edges split", "new edges flipped", "positions committed"; Other: "not part of Loop
// subdivision".
const char* upsample_phase_name(UpsamplePhase phase);
// "phase 3 (new edges flipped)".
std::string upsample_phase_title(UpsamplePhase phase);

struct UpsamplePhaseSpan {
  bool started = false;  // phase 1 always has (it writes nothing); 2-4 once one of their edits is recorded
  size_t first = 0;      // index of the phase's first edit (phase 1: 0)
  size_t last = 0;       // index of its last edit (phase 1: none, 0)
  size_t writes = 0;     // edits of the phase (phase 1: 0 unless written by hand, which it cannot be)
};

struct UpsamplePhases {
  static constexpr size_t kNearCreation = 48;
  static constexpr size_t kMaxProblems = 8;

  std::vector<UpsamplePhase> phase_of;      // one per edit
  std::array<UpsamplePhaseSpan, 5> span{};  // [1] .. [4]; [0] unused
  size_t other_writes = 0;                  // edits of phase Other
  std::vector<std::string> problems;

  size_t size() const { return phase_of.size(); }
  // The phase of write k (1-based; k = 0, before any write, is phase 1; past the end, the last write's).
  UpsamplePhase phase_at(size_t k) const;
  // The replay position that shows phase p's first write (phase 1: 0); nothing when p never started.
  std::optional<size_t> start_position(UpsamplePhase p) const;
  // The replay position where phase p is complete: just after its last write. Phase 1 (no writes) and a phase that
  // never started end where the phases below them left the mesh: just before the first write of a higher phase
  // (the end of the recording when there is none).
  size_t end_position(UpsamplePhase p) const;
  // The start position of the first started phase that begins after position k / the last one that begins
  // before it; nothing when there is none. Phases are visited in the order they start in the recording.
  std::optional<size_t> next_phase_position(size_t k) const;
  std::optional<size_t> previous_phase_position(size_t k) const;
};

UpsamplePhases find_upsample_phases(std::span<const RecordedEdit> edits);

}  // namespace meshedit
