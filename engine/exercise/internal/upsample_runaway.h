// A runaway upsample: how many changes a finished upsample of a mesh can need (the window stops a recording past
// that), and what to tell a student whose upsample was stopped, from where it was and what it had done.
//
//   upsample_edit_budget(mesh)                     -> 64 (V + E + F) + 4096, at most EditRecorder's default
//   explain_unfinished_upsample(error, before, mine, edits)
//     -> "upsample.lua:38: more than 5504 changes recorded; is there a loop that never ends? It was stopped in
//         phase 2 (edges split) after 5498 splits; the mesh had 18 edges and Loop subdivision splits each of them
//         once: the loop at upsample.lua:38 splits edges that its own splits made."
//
// Invariants:
// - The explanation starts with the error as the runtime gave it, so the student file's line ("upsample.lua:38:")
//   comes first; when the error has no such line, the line of the last recorded write is put first instead.
// - What it says was done comes from the recording when there is one (the phase it was in, by
//   upsample_phases.h), else from the mesh it left (one new vertex per split).
// - Pure and total: any input gives a sentence; nothing throws but std::bad_alloc.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "core/edit_log.h"
#include "core/halfedge_mesh.h"

namespace meshedit {

size_t upsample_edit_budget(const HalfedgeMesh& before);

// `mine`: the mesh as the stopped run left it (null when there is none); `edits`: its recording (may be empty).
std::string explain_unfinished_upsample(const std::string& error, const HalfedgeMesh& before, const HalfedgeMesh* mine,
                                        std::span<const RecordedEdit> edits);

}  // namespace meshedit
