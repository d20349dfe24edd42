// The rows and spots of repair_marks.h, from a repair report.
#include "app/repair_marks.h"

#include <algorithm>

namespace meshedit {

ElementRef RepairMarks::first_spot(size_t row) const {
  if (row >= spots.size()) return {};
  const RepairSpots& s = spots[row];
  if (!s.vertices.empty()) return VertexId(s.vertices.front());
  if (!s.faces.empty()) return FaceId::face(s.faces.front());
  return {};
}

std::vector<ElementRef> RepairMarks::all_spots() const {
  std::vector<ElementRef> all;
  for (const RepairSpots& s : spots) {
    for (uint32_t v : s.vertices) all.push_back(VertexId(v));
    for (uint32_t f : s.faces) all.push_back(FaceId::face(f));
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

RepairMarks marks_of_repair(const RepairReport& report) {
  RepairMarks marks;
  marks.summary = report.summary();
  marks.rows = report.changes;
  marks.spots = report.spots;
  return marks;
}

}  // namespace meshedit
