// RepairMarks: what File > Open a repaired copy left for the Repairs tab and the mesh view: the report's summary,
// one row per change (its sentence, in the file's numbers) and the row's spots in the repaired mesh (output vertex
// and face indices, which are the document's VertexId and FaceId: core/mesh_repair.h).
//
// Invariants:
// - rows.size() == spots.size(); a row with empty spots (unused vertices dropped) selects nothing.
// - The spots are current only for the mesh exactly as it was opened: the document generation and mesh version
//   recorded then. Opening another file (a new generation) or any edit, undo included (a new version), makes them
//   stale for good: the view stops highlighting them and the rows stop selecting; the rows stay listed (opening
//   another file with open() empties the marks, and the Repairs tab goes).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/ids.h"
#include "core/mesh_repair.h"

namespace meshedit {

struct RepairMarks {
  std::string summary;
  std::vector<std::string> rows;
  std::vector<RepairSpots> spots;
  uint64_t generation = 0;  // the document's generation and mesh version the spots belong to
  uint64_t version = 0;

  bool empty() const { return rows.empty() && summary.empty(); }
  bool current(uint64_t document_generation, uint64_t mesh_version) const {
    return !empty() && generation == document_generation && version == mesh_version;
  }
  // What clicking row i selects: its first vertex, else its first face; invalid when it has neither.
  ElementRef first_spot(size_t row) const;
  // Every row's spots, vertices and faces, each once, sorted.
  std::vector<ElementRef> all_spots() const;
};

RepairMarks marks_of_repair(const RepairReport& report);  // generation and version left for the caller

}  // namespace meshedit
