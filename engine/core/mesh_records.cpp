// A HalfedgeMesh with every record, as text and back (see mesh_records.h).
#include "core/mesh_records.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <sstream>
#include <vector>

#include "core/mesh_error.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

constexpr const char* kHeader = "meshedit mesh records 1";

void put(std::string& out, ElementRef ref) {
  out += ' ';
  out += format_id(ref);
}

struct Reader {
  const std::string& name;
  size_t line = 0;

  [[noreturn]] void fail(const std::string& why) const {
    throw MeshError(name + ":" + std::to_string(line) + ": " + why);
  }

  // A pointer of kind `kind` ("-" for none; a face pointer may name a boundary loop).
  ElementRef pointer(const std::string& word, ElementKind kind) const {
    if (word == "-") return {};
    const std::optional<ElementRef> ref = parse_element(word);
    const bool face_kind = kind == ElementKind::Face && ref && ref->kind == ElementKind::Boundary;
    if (!ref || (ref->kind != kind && !face_kind)) fail("'" + word + "' is not a " + kind_name(kind) + " id");
    return *ref;
  }
};

}  // namespace

std::string format_mesh_records(const HalfedgeMesh& m) {
  std::string out = kHeader;
  out += '\n';
  for (uint32_t i = 0; i < m.vertex_capacity(); ++i) {
    const VertexId v(i);
    out += "v " + std::to_string(i) + (m.alive(v) ? " +" : " -");
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_number(out, m.position(v)[k]);
    }
    put(out, m.halfedge(v));
    out += '\n';
  }
  for (uint32_t i = 0; i < m.halfedge_capacity(); ++i) {
    const HalfedgeRecord& r = m.record(HalfedgeId(i));
    out += "h " + std::to_string(i) + (m.alive(HalfedgeId(i)) ? " +" : " -");
    put(out, r.next);
    put(out, r.twin);
    put(out, r.vertex);
    put(out, r.edge);
    put(out, r.face);
    out += '\n';
  }
  for (uint32_t i = 0; i < m.edge_capacity(); ++i) {
    out += "e " + std::to_string(i) + (m.alive(EdgeId(i)) ? " +" : " -");
    put(out, m.halfedge(EdgeId(i)));
    out += '\n';
  }
  for (uint32_t i = 0; i < m.face_capacity(); ++i) {
    out += "f " + std::to_string(i) + (m.alive(FaceId::face(i)) ? " +" : " -");
    put(out, m.halfedge(FaceId::face(i)));
    out += '\n';
  }
  for (uint32_t i = 0; i < m.boundary_capacity(); ++i) {
    out += "b " + std::to_string(i) + (m.alive(FaceId::boundary(i)) ? " +" : " -");
    put(out, m.halfedge(FaceId::boundary(i)));
    out += '\n';
  }
  return out;
}

namespace {

constexpr std::string_view kKinds = "vhefb";

struct Row {
  char kind;
  bool alive;
  std::vector<std::string> words;  // after the slot and the flag
  size_t line;
};

struct Counts {
  uint32_t of[5] = {0, 0, 0, 0, 0};  // v h e f b
  bool holds(ElementRef ref) const {
    if (!ref.valid()) return true;
    switch (ref.kind) {
      case ElementKind::Vertex: return ref.index < of[0];
      case ElementKind::Halfedge: return ref.index < of[1];
      case ElementKind::Edge: return ref.index < of[2];
      case ElementKind::Face: return ref.index < of[3];
      case ElementKind::Boundary: return ref.index < of[4];
    }
    return false;
  }
};

// The header, then each line as a row; the slots of each kind counted.
std::vector<Row> read_rows(std::string_view text, Reader& reader, Counts& counts) {
  std::istringstream in{std::string(text)};
  std::string line;
  std::getline(in, line);
  reader.line = 1;
  if (line != kHeader) reader.fail("not a MeshEdit mesh records text (no \"" + std::string(kHeader) + "\")");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    ++reader.line;
    if (line.empty()) continue;
    std::istringstream words(line);
    std::string kind, slot, flag;
    words >> kind >> slot >> flag;
    const size_t k = kind.size() == 1 ? kKinds.find(kind[0]) : std::string::npos;
    if (k == std::string::npos) reader.fail("'" + kind + "' is not v, h, e, f or b");
    if (slot != std::to_string(counts.of[k])) {
      reader.fail(kind + " " + slot + " is out of order (expected " + std::to_string(counts.of[k]) + ")");
    }
    if (flag != "+" && flag != "-") reader.fail("'" + flag + "' is not + (live) or - (dead)");
    ++counts.of[k];
    Row row{kind[0], flag == "+", {}, reader.line};
    for (std::string w; words >> w;) row.words.push_back(w);
    const size_t wanted = kind == "v" ? 4 : kind == "h" ? 5 : 1;
    if (row.words.size() != wanted) reader.fail(kind + " " + slot + " needs " + std::to_string(wanted) + " values");
    rows.push_back(std::move(row));
  }
  return rows;
}

double number(const Reader& reader, const std::string& word) {
  char* end = nullptr;
  const double x = std::strtod(word.c_str(), &end);
  if (end == word.c_str() || *end != '\0') reader.fail("'" + word + "' is not a number");
  return x;
}

// Sets the pointers (and a vertex's position) of slot `slot` from its row.
void apply(const Row& row, uint32_t slot, const Reader& reader, const Counts& counts, HalfedgeMesh& mesh) {
  const auto ptr = [&](size_t word, ElementKind kind) {
    const ElementRef ref = reader.pointer(row.words[word], kind);
    if (!counts.holds(ref)) reader.fail(row.words[word] + " is not a slot of this text");
    return ref;
  };
  const auto halfedge = [&](size_t word) { return HalfedgeId(ptr(word, ElementKind::Halfedge).index); };
  switch (row.kind) {
    case 'v':
      mesh.set_position(VertexId(slot), glm::dvec3(number(reader, row.words[0]), number(reader, row.words[1]),
                                                   number(reader, row.words[2])));
      mesh.set_halfedge(VertexId(slot), halfedge(3));
      break;
    case 'h':
      mesh.set_next(HalfedgeId(slot), halfedge(0));
      mesh.set_twin(HalfedgeId(slot), halfedge(1));
      mesh.set_vertex(HalfedgeId(slot), VertexId(ptr(2, ElementKind::Vertex).index));
      mesh.set_edge(HalfedgeId(slot), EdgeId(ptr(3, ElementKind::Edge).index));
      mesh.set_face(HalfedgeId(slot), ptr(4, ElementKind::Face).face_id());
      break;
    case 'e': mesh.set_halfedge(EdgeId(slot), halfedge(0)); break;
    case 'f': mesh.set_halfedge(FaceId::face(slot), halfedge(0)); break;
    default: mesh.set_halfedge(FaceId::boundary(slot), halfedge(0)); break;
  }
}

void kill(HalfedgeMesh& mesh, char kind, uint32_t slot) {
  switch (kind) {
    case 'v': mesh.delete_element(VertexId(slot)); break;
    case 'h': mesh.delete_element(HalfedgeId(slot)); break;
    case 'e': mesh.delete_element(EdgeId(slot)); break;
    case 'f': mesh.delete_element(FaceId::face(slot)); break;
    default: mesh.delete_element(FaceId::boundary(slot)); break;
  }
}

}  // namespace

HalfedgeMesh parse_mesh_records(std::string_view text, const std::string& name) {
  Reader reader{name};
  Counts counts;
  const std::vector<Row> rows = read_rows(text, reader, counts);
  HalfedgeMesh mesh;
  mesh.reserve(counts.of[0], counts.of[1], counts.of[2], counts.of[3]);
  for (uint32_t i = 0; i < counts.of[0]; ++i) mesh.new_vertex();
  for (uint32_t i = 0; i < counts.of[1]; ++i) mesh.new_halfedge();
  for (uint32_t i = 0; i < counts.of[2]; ++i) mesh.new_edge();
  for (uint32_t i = 0; i < counts.of[3]; ++i) mesh.new_face();
  for (uint32_t i = 0; i < counts.of[4]; ++i) mesh.new_boundary();
  uint32_t slots[5] = {0, 0, 0, 0, 0};
  for (const Row& row : rows) {
    reader.line = row.line;
    apply(row, slots[kKinds.find(row.kind)]++, reader, counts, mesh);
  }
  // Dead last: every slot was made live and set first.
  std::fill(std::begin(slots), std::end(slots), 0);
  for (const Row& row : rows) {
    const uint32_t slot = slots[kKinds.find(row.kind)]++;
    if (!row.alive) kill(mesh, row.kind, slot);
  }
  return mesh;
}

}  // namespace meshedit
