// A runaway upsample's budget and explanation (see upsample_runaway.h for the contract).
#include "exercise/internal/upsample_runaway.h"

#include <algorithm>
#include <cctype>

#include "core/value_format.h"
#include "exercise/upsample_phases.h"
#include "script/edit_recorder.h"

namespace meshedit {
namespace {

// "name.lua:12" when the error starts with it, else "".
std::string leading_line(const std::string& error) {
  const size_t lua = error.find(".lua:");
  if (lua == std::string::npos || error.find(' ') < lua) return "";
  size_t end = lua + 5;
  while (end < error.size() && std::isdigit(static_cast<unsigned char>(error[end]))) ++end;
  return end > lua + 5 ? error.substr(0, end) : "";
}

}  // namespace

size_t upsample_edit_budget(const HalfedgeMesh& before) {
  // A finished upsample makes E splits, at most 2E flips and V + E position writes; a split written by hand is
  // about 40 writes, a flip about 10. 64 per element is above all of that.
  const size_t elements = before.num_vertices() + before.num_edges() + before.num_faces();
  return std::min(EditRecorder::kDefaultMaxEdits, 64 * elements + 4096);
}

std::string explain_unfinished_upsample(const std::string& error, const HalfedgeMesh& before, const HalfedgeMesh* mine,
                                        std::span<const RecordedEdit> edits) {
  std::string where = leading_line(error);
  std::string text = error;
  if (where.empty() && !edits.empty() && !edits.back().where.empty()) {
    where = edits.back().where;
    text = where + ": " + error;
  }
  const size_t edges = before.num_edges();
  size_t splits = 0;
  std::string phase;
  if (!edits.empty()) {
    const UpsamplePhases phases = find_upsample_phases(edits);
    splits = phases.span[size_t(UpsamplePhase::Split)].writes;
    phase = upsample_phase_title(phases.phase_at(edits.size()));
  } else if (mine && mine->num_vertices() >= before.num_vertices()) {
    splits = mine->num_vertices() - before.num_vertices();  // one new vertex per split
  }
  const std::string at = where.empty() ? "" : " at " + where;
  text += text.empty() || text.back() == '.' || text.back() == '?' ? " " : ". ";
  if (splits > edges) {
    text += "It was stopped" + (phase.empty() ? std::string() : " in " + phase) + " after " +
            plural(splits, "split", "splits") + (edits.empty() ? " (one new vertex each)" : "") + "; the mesh had " +
            plural(edges, "edge", "edges") + " and Loop subdivision splits each of them once: the loop" + at +
            " splits edges that its own splits made. List the original edges before the first split and split only "
            "those.";
  } else if (edits.empty() && (!mine || mine->same_as(before))) {
    text += "It was stopped before it changed the mesh: a loop" + at +
            " never ends. Look at what its condition waits for: a `while` whose variables never change, or a walk "
            "(`repeat ... h = h.twin.next until h == start`) that never comes back to its start.";
  } else {
    text += "It was stopped" + (phase.empty() ? std::string() : " in " + phase) + " after " +
            plural(splits, "split", "splits") + " of the mesh's " + std::to_string(edges) + ": a loop" + at +
            " never ends. Look at what its condition waits for: a `while` whose variables never change, or a walk "
            "(`repeat ... h = h.twin.next until h == start`) that never comes back to its start.";
  }
  return text;
}

}  // namespace meshedit
