// The Inspector panel and the element facts it shows (see inspector.h). Every stored field is read only after
// in_range(); walks use the mesh's bounded iterators.
#include "ui/inspector.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "core/translation.h"
#include "core/value_format.h"
#include "ui/flow_layout.h"

namespace meshedit {
namespace {

bool live(const HalfedgeMesh& mesh, ElementRef ref) { return reference_state(mesh, ref) == RefState::Live; }

// Where `h` points: next.vertex, if both can be read.
VertexId head_of(const HalfedgeMesh& mesh, HalfedgeId h) {
  const HalfedgeId n = mesh.next(h);
  return in_range(mesh, n) ? mesh.vertex(n) : VertexId();
}

void inspect_walk(const HalfedgeMesh& mesh, ElementFacts& facts, size_t max_listed) {
  const auto add = [&](HalfedgeId h, VertexId v) {
    if (facts.walk.size() < max_listed) facts.walk.push_back({h, v});
    ++facts.walked;
  };
  const ElementRef e = facts.element;
  if (e.kind == ElementKind::Vertex) {
    facts.closed = mesh.for_each_outgoing(VertexId(e.index), [&](HalfedgeId h) {
      const HalfedgeId t = mesh.twin(h);
      add(h, in_range(mesh, t) ? mesh.vertex(t) : VertexId());
    });
  } else {
    facts.closed = mesh.for_each_face_halfedge(e.face_id(), [&](HalfedgeId h) { add(h, mesh.vertex(h)); });
  }
}

}  // namespace

ElementFacts inspect_element(const HalfedgeMesh& mesh, ElementRef element, size_t max_listed) {
  ElementFacts facts;
  facts.element = element;
  facts.state = reference_state(mesh, element);
  if (facts.state != RefState::Live) return facts;
  switch (element.kind) {
    case ElementKind::Vertex:
      inspect_walk(mesh, facts, max_listed);
      facts.is_boundary = mesh.is_boundary(VertexId(element.index));
      break;
    case ElementKind::Face:
    case ElementKind::Boundary:
      inspect_walk(mesh, facts, max_listed);
      facts.is_boundary = element.kind == ElementKind::Boundary;
      break;
    case ElementKind::Halfedge: {
      const HalfedgeId h(element.index);
      facts.prev = mesh.prev(h);
      facts.head = head_of(mesh, h);
      facts.is_boundary = mesh.face(h).is_boundary();
      break;
    }
    case ElementKind::Edge: {
      const EdgeId e(element.index);
      const HalfedgeId h = mesh.halfedge(e);
      if (!in_range(mesh, h)) break;
      facts.edge_twin = mesh.twin(h);
      facts.edge_ends[0] = mesh.vertex(h);
      facts.edge_faces[0] = mesh.face(h);
      if (in_range(mesh, facts.edge_twin)) {
        facts.edge_ends[1] = mesh.vertex(facts.edge_twin);
        facts.edge_faces[1] = mesh.face(facts.edge_twin);
      }
      facts.is_boundary = facts.edge_faces[0].is_boundary() || facts.edge_faces[1].is_boundary();
      if (live(mesh, facts.edge_ends[0]) && live(mesh, facts.edge_ends[1]))
        facts.length = glm::distance(mesh.position(facts.edge_ends[0]), mesh.position(facts.edge_ends[1]));
      break;
    }
  }
  return facts;
}

namespace {

struct Drawer {
  const HalfedgeMesh& mesh;
  Selection& selection;
  UiProbe* probe;

  // label and text use no field, but are called on the rows like link and position, as one set of row kinds.
  void label(const char* text) {  // NOLINT(readability-convert-member-functions-to-static)
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(text);
    ImGui::TableSetColumnIndex(1);
  }
  // `shown`: the row's words when they are not the field's code name (which names the link in the probe).
  void link(const char* field, ElementRef ref, const char* shown = nullptr) {
    label(shown ? shown : field);
    element_link(mesh, ref, selection, field, probe);
  }
  void text(const char* field, const std::string& value) {  // NOLINT(readability-convert-member-functions-to-static)
    label(field);
    ImGui::TextUnformatted(value.c_str());
  }
  void position(VertexId v) {
    if (!live(mesh, v)) return;
    ImGui::SameLine();
    ImGui::TextDisabled("%s", format_position(mesh.position(v)).c_str());
  }
};

const char* yes_no(bool b) { return tr(b ? "yes" : "no"); }

// `closed` and `open`: the heading's templates ("halfedge cycle ({count}, closed)"), by whether the walk closed.
void draw_walk(Drawer& d, const ElementFacts& facts, const char* closed, const char* open, const char* vertex_role) {
  const std::string heading = tr_format(facts.closed ? closed : open, {{"count", std::to_string(facts.walked)}});
  if (!facts.closed) ImGui::TextColored(ui_colors::broken(), "%s", heading.c_str());
  else ImGui::TextUnformatted(heading.c_str());
  for (size_t i = 0; i < facts.walk.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    ImGui::Bullet();
    element_link(d.mesh, facts.walk[i].halfedge, d.selection, "walk-halfedge", d.probe);
    ImGui::SameLine();
    ImGui::TextDisabled("%s", tr(vertex_role));
    ImGui::SameLine();
    element_link(d.mesh, facts.walk[i].vertex, d.selection, "walk-vertex", d.probe);
    ImGui::PopID();
  }
  if (facts.walked > facts.walk.size()) {
    ImGui::TextDisabled(
        "%s",
        tr_format("... {count} more", {{"count", std::to_string(unsigned(facts.walked - facts.walk.size()))}}).c_str());
  }
}

void draw_fields(Drawer& d, const ElementFacts& facts, bool alive) {
  const HalfedgeMesh& mesh = d.mesh;
  const ElementRef e = facts.element;
  if (!ImGui::BeginTable("fields", 2, ImGuiTableFlags_SizingFixedFit)) return;
  switch (e.kind) {
    case ElementKind::Halfedge: {
      const HalfedgeId h(e.index);
      d.link("next", mesh.next(h));
      d.link("twin", mesh.twin(h));
      d.link("vertex", mesh.vertex(h));
      d.position(mesh.vertex(h));
      d.link("edge", mesh.edge(h));
      d.link("face", mesh.face(h));
      if (alive) {
        d.link("prev", facts.prev);
        if (!facts.prev.valid()) {
          ImGui::SameLine();
          ImGui::TextDisabled("%s", tr("(face cycle broken)"));
        }
        d.link("head", facts.head, tr("head"));
        ImGui::SameLine();
        ImGui::TextDisabled("next.vertex");
        d.text(tr("on boundary"), yes_no(facts.is_boundary));
      }
      break;
    }
    case ElementKind::Vertex: {
      const VertexId v(e.index);
      d.link("halfedge", mesh.halfedge(v));
      const glm::dvec3& p = mesh.position(v);
      d.text("x", format_number(p.x));
      d.text("y", format_number(p.y));
      d.text("z", format_number(p.z));
      if (alive) {
        const auto degree = facts.degree();
        d.text(tr("degree"), degree ? std::to_string(*degree) : std::string(tr("- (fan does not close)")));
        d.text(tr("on boundary"), yes_no(facts.is_boundary));
      }
      break;
    }
    case ElementKind::Edge: {
      d.link("halfedge", mesh.halfedge(EdgeId(e.index)));
      if (alive) {
        d.link("twin", facts.edge_twin);
        ImGui::SameLine();
        ImGui::TextDisabled("halfedge.twin");
        d.link("ends", facts.edge_ends[0], tr("ends"));
        ImGui::SameLine();
        element_link(mesh, facts.edge_ends[1], d.selection, "end2", d.probe);
        d.link("faces", facts.edge_faces[0], tr("faces"));
        ImGui::SameLine();
        element_link(mesh, facts.edge_faces[1], d.selection, "face2", d.probe);
        d.text(tr("length"), facts.length ? format_number(*facts.length) : std::string("-"));
        d.text(tr("on boundary"), yes_no(facts.is_boundary));
      }
      break;
    }
    case ElementKind::Face:
    case ElementKind::Boundary: {
      d.link("halfedge", mesh.halfedge(e.face_id()));
      if (alive) {
        const auto degree = facts.degree();
        d.text(tr("degree"), degree ? std::to_string(*degree) : std::string(tr("- (cycle does not close)")));
        d.text(tr("boundary loop"), yes_no(facts.is_boundary));
      }
      break;
    }
  }
  ImGui::EndTable();
}

}  // namespace

bool draw_inspector_contents(MeshDocument& doc, Selection& selection, InspectorState& state) {
  const ElementRef before = selection.selected;
  const ElementRef e = selection.selected;
  if (!e.valid()) {
    text_wrapped_at_spaces(
        tr("Nothing selected. Click an element in the view or a row of the pointer tables; "
           "N T V E F H walk the pointers."));
    return false;
  }
  const RefState st = reference_state(doc.mesh, e);
  if (st == RefState::OutOfRange) {
    ImGui::TextColored(ui_colors::broken(), "%s", reference_problem(doc.mesh, e).c_str());
    return false;
  }
  if (!state.facts_filled || state.facts.element != e || state.facts_generation != doc.generation ||
      state.facts_version != doc.mesh.version()) {
    state.facts = inspect_element(doc.mesh, e, state.max_listed);
    state.facts_filled = true;
    state.facts_generation = doc.generation;
    state.facts_version = doc.mesh.version();
    ++state.facts_computations;
  }
  const ElementFacts facts = state.facts;  // a copy: a click below may change the selection mid-draw
  const bool alive = st == RefState::Live;

  ImGui::Text("%s  %s", format_id(e).c_str(), tr(kind_name(e.kind)));
  ImGui::SameLine();
  if (alive) ImGui::TextColored(ui_colors::valid(), "%s", tr("alive"));
  else ImGui::TextColored(ui_colors::dead(), "%s", tr("dead: deleted, fields keep their last values"));
  Drawer d{doc.mesh, selection, state.probe};
  draw_fields(d, facts, alive);
  if (alive && (e.kind == ElementKind::Face || e.kind == ElementKind::Boundary))
    draw_walk(d, facts, "halfedge cycle ({count}, closed)", "halfedge cycle ({count} steps, does not close)", "from");
  if (alive && e.kind == ElementKind::Vertex) {
    draw_walk(d, facts, "outgoing halfedges ({count}, closed)", "outgoing halfedges ({count} steps, does not close)",
              "to");
  }
  return selection.selected != before;
}

bool draw_inspector(MeshDocument& doc, Selection& selection, InspectorState& state) {
  if (!state.open) return false;
  bool changed = false;
  default_window_size(ImVec2(340, 460));
  if (ImGui::Begin(tr_label("Inspector"), &state.open)) changed = draw_inspector_contents(doc, selection, state);
  ImGui::End();
  return changed;
}

}  // namespace meshedit
