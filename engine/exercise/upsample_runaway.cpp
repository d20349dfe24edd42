// A runaway upsample's budget and explanation (see upsample_runaway.h for the contract).
#include "exercise/internal/upsample_runaway.h"

#include <algorithm>
#include <cctype>

#include "core/translation.h"
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
  text += text.empty() || text.back() == '.' || text.back() == '?' ? " " : ". ";
  // The phase is known from the recording: there is one exactly when `edits` is not empty.
  const MessageParts at = {{"where", where}};
  if (splits > edges) {
    const MessageParts parts = {
        {"phase", phase},
        {"splits", tr_format(splits == 1 ? "{count} split" : "{count} splits", {{"count", std::to_string(splits)}})},
        {"edges", tr_format(edges == 1 ? "{count} edge" : "{count} edges", {{"count", std::to_string(edges)}})},
        {"loop", where.empty() ? std::string(tr("the loop")) : tr_format("the loop at {where}", at)}};
    text += edits.empty()
                ? tr_format(
                      "It was stopped after {splits} (one new vertex each); the mesh had {edges} and Loop "
                      "subdivision splits each of them once: {loop} splits edges that its own splits made. List "
                      "the original edges before the first split and split only those.",
                      parts)
                : tr_format(
                      "It was stopped in {phase} after {splits}; the mesh had {edges} and Loop subdivision "
                      "splits each of them once: {loop} splits edges that its own splits made. List the original "
                      "edges before the first split and split only those.",
                      parts);
    return text;
  }
  const MessageParts parts = {
      {"phase", phase},
      {"splits", tr_format(splits == 1 ? "{count} split" : "{count} splits", {{"count", std::to_string(splits)}})},
      {"edges", std::to_string(edges)},
      {"loop", where.empty() ? std::string(tr("a loop")) : tr_format("a loop at {where}", at)}};
  if (edits.empty() && (!mine || mine->same_as(before))) {
    text += tr_format(
        "It was stopped before it changed the mesh: {loop} never ends. Look at what its condition "
        "waits for: a `while` whose variables never change, or a walk (`repeat ... h = h.twin.next "
        "until h == start`) that never comes back to its start.",
        parts);
  } else if (edits.empty()) {
    text += tr_format(
        "It was stopped after {splits} of the mesh's {edges}: {loop} never ends. Look at what its "
        "condition waits for: a `while` whose variables never change, or a walk (`repeat ... h = "
        "h.twin.next until h == start`) that never comes back to its start.",
        parts);
  } else {
    text += tr_format(
        "It was stopped in {phase} after {splits} of the mesh's {edges}: {loop} never ends. Look at "
        "what its condition waits for: a `while` whose variables never change, or a walk (`repeat ... "
        "h = h.twin.next until h == start`) that never comes back to its start.",
        parts);
  }
  return text;
}

}  // namespace meshedit
