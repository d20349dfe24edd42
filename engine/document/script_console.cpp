// The console bound to the document: see script_console.h for the contract.
#include "document/script_console.h"

#include <new>
#include <optional>
#include <utility>

#include "core/change_journal.h"
#include "core/mesh_patch.h"

namespace meshedit {
namespace {

// The first line of `code`, shortened, for undo labels ("console: m:flip(m:edge(3))").
std::string label_of(const std::string& code) {
  std::string first = code.substr(0, code.find('\n'));
  if (first.size() > 60) first = first.substr(0, 57) + "...";
  return first;
}

}  // namespace

ScriptConsole::ScriptConsole() : mesh_(std::make_shared<HalfedgeMesh>()) { repl_.set_mesh(mesh_); }

void ScriptConsole::sync_from(const MeshDocument& doc) {
  // A console mesh changed since it was synced (a line that threw past submit's bookkeeping) is copied afresh.
  const bool untouched = mesh_->version() == mesh_version_when_synced_;
  if (untouched && doc.generation == synced_generation_ && doc.mesh.version() == synced_version_) return;
  const bool one_local_change_behind =
      untouched && doc.generation == synced_generation_ && synced_version_ != UINT64_MAX && doc.last.patch &&
      doc.last.version_before == synced_version_ && doc.last.version_after == doc.mesh.version();
  if (one_local_change_behind) {
    doc.last.patch->apply(*mesh_, true);
    mesh_->bump_version_above(mesh_->version());  // apply() keeps the version: the script's undo must see a change
  } else {
    *mesh_ = doc.mesh;  // in place: handles in globals keep pointing at the console's mesh
  }
  synced_generation_ = doc.generation;
  synced_version_ = doc.mesh.version();
  mesh_version_when_synced_ = mesh_->version();
}

void ScriptConsole::submit(MeshDocument& doc, const Selection& selection, const std::string& code) {
  if (!repl_.record(code)) return;
  sync_from(doc);
  repl_.set_selected(selection.selected);
  const uint64_t version_before = mesh_->version();
  bool failed = false;
  std::optional<MeshPatch> patch;
  {
    ChangeJournal journal(*mesh_);  // what the line writes, slot by slot, unless it rewrites the mesh wholesale
    failed = !repl_.evaluate(code);
    if (mesh_->version() == version_before) return;
    if (!journal.has_snapshot() && !journal.state_before_lost()) {
      try {
        patch = make_patch(journal, *mesh_);
      } catch (const std::bad_alloc&) {
        // The document gets the whole mesh instead.
      }
    }
  }
  const std::string label = std::string(failed ? "console (error): " : "console: ") + label_of(code);
  // A local change reaches the document as the same writes (its journal keeps a patch: no copy of the mesh, the diff
  // and the validation from the patch); anything else as an assignment of the console's mesh.
  const Check done = apply_operation(doc, label, [&](HalfedgeMesh& mesh) {
    if (!patch || !patch->apply_as_edit(mesh)) mesh = *mesh_;
    return Check::yes();
  });
  // Kept, the document's mesh now holds what the console's does (its version may differ): no copy next line.
  synced_generation_ = doc.generation;
  synced_version_ = done.ok ? doc.mesh.version() : UINT64_MAX;
  mesh_version_when_synced_ = mesh_->version();
}

}  // namespace meshedit
