// COLLADA reading (see dae_reader.h). Every number, count and index is checked before it is used; the
// XML depth is bounded by tinyxml2 (TINYXML2_MAX_ELEMENT_DEPTH) and scene nodes are walked with an
// explicit stack, so no input can exhaust the C++ stack.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   XML helpers               local_name, child, children; NodeTransform and Instance (a placed <geometry>)
//   the reader                DaeReader::read: the asset, the scene or every geometry, the meshes appended
//   asset and checked values  read_asset, attributes and numbers checked with their line (fail)
//   geometry                  read_geometry, read_positions (<vertices>, <source>, <accessor>)
//   primitives                read_primitive: <triangles>, <polylist>, <polygons>, <trifans>, <tristrips>
//   corners                   vertex_of, reserve_corners, add_polygons, add_corner_triangles
//   scene                     chosen_scene, compose (node transforms, walked with a stack), transformed, append
//   entry points              parse_dae_file, read_dae_file, parse_dae, read_dae
#include "io/dae_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <tinyxml2.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "io/file_access.h"
#include "io/file_error.h"
#include "io/io_limits.h"
#include "io/text_scanner.h"

namespace meshedit {
namespace {

using tinyxml2::XMLElement;

// ---- XML helpers -----------------------------------------------------------------------------------

// Element name without a namespace prefix ("collada:mesh" -> "mesh").
std::string_view local_name(const XMLElement* e) {
  const std::string_view name = e->Name();
  const size_t colon = name.rfind(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

bool named(const XMLElement* e, std::string_view name) { return local_name(e) == name; }

const XMLElement* child(const XMLElement* parent, std::string_view name) {
  if (parent == nullptr) return nullptr;
  for (const XMLElement* c = parent->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (named(c, name)) return c;
  }
  return nullptr;
}

std::vector<const XMLElement*> children(const XMLElement* parent, std::string_view name) {
  std::vector<const XMLElement*> out;
  if (parent == nullptr) return out;
  for (const XMLElement* c = parent->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (named(c, name)) out.push_back(c);
  }
  return out;
}

std::string tag(const XMLElement* e) { return "<" + std::string(local_name(e)) + ">"; }

// What a geometry instance needs: the node's world transform, or why it could not be computed.
struct NodeTransform {
  glm::dmat4 matrix{1.0};
  const XMLElement* problem_at = nullptr;  // first unsupported transform element on the path, if any
  std::string problem;
};

struct Instance {
  NodeTransform transform;
  const XMLElement* element = nullptr;  // the <instance_geometry>
};

// ---- the reader ------------------------------------------------------------------------------------

class DaeReader {
 public:
  DaeReader(std::string_view text, std::string name) : text_(text), file_(std::move(name)) {}

  DaeFile read() {
    if (text_.find_first_not_of(" \t\r\n") == std::string_view::npos) throw FileError(file_, 1, "file is empty");
    tinyxml2::XMLDocument doc(true, tinyxml2::PRESERVE_WHITESPACE);
    if (doc.Parse(text_.data(), text_.size()) != tinyxml2::XML_SUCCESS) {
      const auto line = static_cast<size_t>(std::max(doc.ErrorLineNum(), 1));
      if (doc.ErrorID() == tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED) {
        throw FileError(file_, line, "XML elements nested deeper than " + std::to_string(TINYXML2_MAX_ELEMENT_DEPTH));
      }
      throw FileError(file_, line, std::string("malformed XML (") + doc.ErrorName() + ")");
    }
    const XMLElement* root = doc.RootElement();
    if (root == nullptr) throw FileError(file_, 1, "no XML element found");
    if (!named(root, "COLLADA")) fail(root, "root element is " + tag(root) + ", expected <COLLADA>");
    DaeFile file;
    file.asset = read_asset(child(root, "asset"));

    // Geometries in library order.
    std::vector<const XMLElement*> geometries;
    std::unordered_map<std::string, size_t> geometry_by_id;
    for (const XMLElement* library : children(root, "library_geometries")) {
      for (const XMLElement* geometry : children(library, "geometry")) {
        if (const char* id = geometry->Attribute("id")) geometry_by_id.emplace(id, geometries.size());
        geometries.push_back(geometry);
      }
    }
    std::vector<std::vector<Instance>> instances(geometries.size());
    collect_instances(root, geometry_by_id, instances);

    PolygonMesh& out = file.mesh;
    for (size_t g = 0; g < geometries.size(); ++g) {
      const PolygonMesh mesh = read_geometry(geometries[g]);
      if (instances[g].empty()) {
        append(out, mesh, geometries[g]);
      } else {
        for (const Instance& instance : instances[g]) {
          append(out, transformed(mesh, instance, geometries[g]), instance.element);
        }
      }
    }
    if (out.num_faces() == 0) throw FileError(file_, "", "file holds no triangles or polygons");
    return file;
  }

 private:
  // ---- asset and checked values --------------------------------------------------------------------

  // <asset>'s <up_axis> and first <contributor>/<authoring_tool>; `asset` may be null (then COLLADA's defaults).
  DaeAsset read_asset(const XMLElement* asset) const {
    DaeAsset out;
    if (const XMLElement* up = child(asset, "up_axis")) {
      const std::string value = trimmed_text(up);
      if (value == "X_UP") out.up_axis = UpAxis::X;
      else if (value == "Y_UP") out.up_axis = UpAxis::Y;
      else if (value == "Z_UP") out.up_axis = UpAxis::Z;
      else fail(up, "<up_axis> is " + quote(value) + ", expected X_UP, Y_UP or Z_UP");
      out.up_axis_tagged = true;
    }
    for (const XMLElement* contributor : children(asset, "contributor")) {
      if (const XMLElement* tool = child(contributor, "authoring_tool")) {
        out.authoring_tool = trimmed_text(tool);
        break;
      }
    }
    return out;
  }

  static std::string trimmed_text(const XMLElement* e) {
    const char* text = e->GetText();
    if (text == nullptr) return {};
    const std::string_view view(text);
    const size_t first = view.find_first_not_of(" \t\r\n\v\f");
    if (first == std::string_view::npos) return {};
    return std::string(view.substr(first, view.find_last_not_of(" \t\r\n\v\f") - first + 1));
  }

  [[noreturn]] void fail(const XMLElement* e, const std::string& message) const {
    throw FileError(file_, static_cast<size_t>(std::max(e->GetLineNum(), 1)), message);
  }
  [[noreturn]] void fail(size_t line, const std::string& message) const { throw FileError(file_, line, message); }

  std::string required_attribute(const XMLElement* e, const char* name) const {
    const char* value = e->Attribute(name);
    if (value == nullptr) fail(e, tag(e) + " has no " + name + " attribute");
    return value;
  }

  // A whole-number attribute in [0, max], or `fallback` when absent.
  uint64_t count_attribute(const XMLElement* e, const char* name, uint64_t fallback, uint64_t max) const {
    const char* value = e->Attribute(name);
    if (value == nullptr) return fallback;
    int64_t number = 0;
    if (to_integer(value, number) != NumberStatus::Ok || number < 0 || static_cast<uint64_t>(number) > max) {
      fail(e, tag(e) + " attribute " + name + "=" + quote(value) + " must be a whole number from 0 to " +
                  std::to_string(max));
    }
    return static_cast<uint64_t>(number);
  }

  // The scanner over an element's text, starting at the line the text starts on.
  TextScanner scanner_for(const XMLElement* e) const {
    const char* text = e->GetText();
    if (text == nullptr) return TextScanner({}, file_, static_cast<size_t>(std::max(e->GetLineNum(), 1)));
    // tinyxml2 reports a text node at its first non-space character; the text itself keeps the
    // whitespace before it, so step back over the line breaks in that whitespace.
    const std::string_view view(text);
    size_t line = static_cast<size_t>(std::max(e->FirstChild()->GetLineNum(), 1));
    for (char c : view.substr(0, view.find_first_not_of(" \t\r\n\v\f"))) {
      if (c == '\n' && line > 1) --line;
    }
    return TextScanner(view, file_, line);
  }

  std::vector<double> read_reals(const XMLElement* e) const {
    TextScanner scanner = scanner_for(e);
    std::vector<double> values;
    const std::string what = "a number in " + tag(e);
    while (auto token = scanner.next()) values.push_back(parse_real(*token, file_, what));
    return values;
  }

  std::vector<uint32_t> read_indices(const XMLElement* e) const {
    TextScanner scanner = scanner_for(e);
    std::vector<uint32_t> values;
    const std::string what = "an index in " + tag(e);
    while (auto token = scanner.next()) {
      values.push_back(static_cast<uint32_t>(parse_integer(*token, file_, what, 0, 0xFFFFFFFEu)));
    }
    return values;
  }

  // The line holding the k-th number of an element's text (found again only when reporting an error).
  size_t line_of_number(const XMLElement* e, size_t k) const {
    TextScanner scanner = scanner_for(e);
    size_t line = scanner.line();
    for (size_t i = 0; i <= k; ++i) {
      auto token = scanner.next();
      if (!token) break;
      line = token->line;
    }
    return line;
  }

  // ---- geometry ------------------------------------------------------------------------------------

  PolygonMesh read_geometry(const XMLElement* geometry) const {
    PolygonMesh mesh;
    const XMLElement* mesh_element = child(geometry, "mesh");
    if (mesh_element == nullptr) return mesh;  // <convex_mesh>, <spline>, <brep>: nothing we draw
    const XMLElement* vertices = child(mesh_element, "vertices");
    if (vertices == nullptr) {
      for (const char* kind : {"triangles", "polylist", "polygons", "trifans", "tristrips"}) {
        if (child(mesh_element, kind) != nullptr) fail(mesh_element, "<mesh> has no <vertices>");
      }
      return mesh;
    }
    mesh.positions = read_positions(mesh_element, vertices);
    const std::string vertices_url = "#" + required_attribute(vertices, "id");
    for (const XMLElement* e = mesh_element->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      const std::string_view kind = local_name(e);
      if (kind == "triangles" || kind == "polylist" || kind == "polygons" || kind == "trifans" || kind == "tristrips") {
        read_primitive(e, vertices_url, mesh);
      }
    }
    return mesh;
  }

  std::vector<glm::dvec3> read_positions(const XMLElement* mesh, const XMLElement* vertices) const {
    const XMLElement* input = nullptr;
    for (const XMLElement* candidate : children(vertices, "input")) {
      const char* semantic = candidate->Attribute("semantic");
      if (semantic != nullptr && std::string_view(semantic) == "POSITION") {
        input = candidate;
        break;
      }
    }
    if (input == nullptr) fail(vertices, "<vertices> has no <input semantic=\"POSITION\">");
    const std::string url = required_attribute(input, "source");
    const XMLElement* source = nullptr;
    for (const XMLElement* candidate : children(mesh, "source")) {
      const char* id = candidate->Attribute("id");
      if (id != nullptr && url == "#" + std::string(id)) {
        source = candidate;
        break;
      }
    }
    if (source == nullptr) fail(input, "<input> refers to " + quote(url) + ", which is not a <source> of this <mesh>");
    const XMLElement* array = child(source, "float_array");
    if (array == nullptr) fail(source, "<source> of positions has no <float_array>");
    const std::vector<double> values = read_reals(array);
    const uint64_t declared = count_attribute(array, "count", values.size(), 0xFFFFFFFFu);
    if (declared != values.size()) {
      fail(array, "<float_array> declares count=\"" + std::to_string(declared) + "\" but holds " +
                      std::to_string(values.size()) + " numbers");
    }

    uint64_t count = values.size() / 3, stride = 3, offset = 0;
    if (const XMLElement* accessor = child(child(source, "technique_common"), "accessor")) {
      if (accessor->Attribute("count") == nullptr) fail(accessor, "<accessor> has no count attribute");
      count = count_attribute(accessor, "count", 0, 0xFFFFFFFFu);
      stride = count_attribute(accessor, "stride", 1, 1u << 20);
      offset = count_attribute(accessor, "offset", 0, 0xFFFFFFFFu);
      if (stride < 3) {
        fail(accessor, "<accessor> stride " + std::to_string(stride) + " is too small for x y z positions");
      }
      if (count > kMaxVertices) fail(accessor, "<accessor> count " + std::to_string(count) + " is too large");
      const uint64_t needed = count == 0 ? 0 : offset + (count - 1) * stride + 3;
      if (needed > values.size()) {
        fail(accessor, "<accessor> reads " + std::to_string(needed) + " numbers (count=" + std::to_string(count) +
                           " stride=" + std::to_string(stride) + " offset=" + std::to_string(offset) +
                           "), but <float_array> holds " + std::to_string(values.size()));
      }
    } else if (values.size() % 3 != 0) {
      fail(array, "<float_array> holds " + std::to_string(values.size()) + " numbers, not a multiple of 3");
    }
    if (count > kMaxVertices) {
      fail(array, "<float_array> holds more than " + std::to_string(kMaxVertices) + " positions");
    }

    std::vector<glm::dvec3> positions;
    positions.reserve(count);
    for (uint64_t i = 0; i < count; ++i) {
      const size_t at = offset + i * stride;
      positions.emplace_back(values[at], values[at + 1], values[at + 2]);
    }
    return positions;
  }

  // ---- primitives ----------------------------------------------------------------------------------

  // How a primitive's <p> lists its corners (`stride` indices per corner, the vertex index at `vertex_offset`), and
  // how many polygons, fans or strips it says it holds.
  struct PrimitiveLayout {
    std::string kind;  // "triangles", "polylist", "polygons", "trifans" or "tristrips"
    uint64_t stride = 1;
    uint64_t vertex_offset = 0;
    std::optional<uint64_t> declared_count;  // the count attribute, when there is one
  };

  PrimitiveLayout read_layout(const XMLElement* primitive, const std::string& vertices_url) const {
    PrimitiveLayout layout{std::string(local_name(primitive))};
    const XMLElement* vertex_input = nullptr;
    for (const XMLElement* input : children(primitive, "input")) {
      const std::string semantic = required_attribute(input, "semantic");
      if (input->Attribute("offset") == nullptr) fail(input, "<input semantic=" + quote(semantic) + "> has no offset");
      const uint64_t offset = count_attribute(input, "offset", 0, 1u << 16);
      layout.stride = std::max(layout.stride, offset + 1);
      if (semantic == "VERTEX" && vertex_input == nullptr) {
        vertex_input = input;
        layout.vertex_offset = offset;
      }
    }
    if (vertex_input == nullptr) fail(primitive, "<" + layout.kind + "> has no <input semantic=\"VERTEX\">");
    const std::string url = required_attribute(vertex_input, "source");
    if (url != vertices_url) {
      fail(vertex_input, "<input semantic=\"VERTEX\"> refers to " + quote(url) +
                             ", but the <vertices> of this mesh is " + quote(vertices_url));
    }
    const uint64_t declared = count_attribute(primitive, "count", 0, 0xFFFFFFFFu);
    if (primitive->Attribute("count") != nullptr) layout.declared_count = declared;
    return layout;
  }

  // Refuses a primitive whose count attribute, when it has one, is not the number of `noun` it holds.
  void check_count(const XMLElement* primitive, const PrimitiveLayout& layout, uint64_t found, const char* noun) const {
    if (layout.declared_count && *layout.declared_count != found) {
      fail(primitive, "<" + layout.kind + " count=\"" + std::to_string(*layout.declared_count) + "\"> but it holds " +
                          std::to_string(found) + " " + noun);
    }
  }

  // The corners a <p> holds: its indices, `stride` per corner.
  uint64_t corner_count(const XMLElement* p, const PrimitiveLayout& layout,
                        const std::vector<uint32_t>& indices) const {
    if (indices.size() % layout.stride != 0) {
      fail(p, "<p> of <" + layout.kind + "> has " + std::to_string(indices.size()) +
                  " indices, expected a multiple of " + std::to_string(layout.stride));
    }
    return indices.size() / layout.stride;
  }

  void read_primitive(const XMLElement* primitive, const std::string& vertices_url, PolygonMesh& mesh) const {
    const PrimitiveLayout layout = read_layout(primitive, vertices_url);
    if (layout.kind == "triangles" || layout.kind == "polylist") {
      read_one_p(primitive, layout, mesh);
    } else {
      read_p_each(primitive, layout, mesh);
    }
  }

  // <triangles>, <polylist>: every polygon in one <p>, their sizes 3 or given by <vcount>.
  void read_one_p(const XMLElement* primitive, const PrimitiveLayout& layout, PolygonMesh& mesh) const {
    const std::vector<const XMLElement*> ps = children(primitive, "p");
    if (ps.size() > 1) fail(ps[1], "<" + layout.kind + "> has more than one <p>");
    const XMLElement* p = ps.empty() ? nullptr : ps[0];
    const std::vector<uint32_t> indices = p ? read_indices(p) : std::vector<uint32_t>{};
    const uint64_t corners = corner_count(p, layout, indices);
    std::vector<uint32_t> sizes;
    if (layout.kind == "triangles") {
      if (corners % 3 != 0) {
        fail(p, "<p> of <triangles> holds " + std::to_string(corners) + " corners, expected a multiple of 3");
      }
      sizes.assign(corners / 3, 3);
      check_count(primitive, layout, sizes.size(), "triangles");
    } else {
      sizes = polylist_sizes(primitive, p, corners);
      check_count(primitive, layout, sizes.size(), "polygons");
    }
    add_polygons(p, indices, layout.stride, layout.vertex_offset, sizes, mesh);
  }

  // The polygon sizes of a <polylist> (its <vcount>), checked to add up to the `corners` of its <p>.
  std::vector<uint32_t> polylist_sizes(const XMLElement* primitive, const XMLElement* p, uint64_t corners) const {
    std::vector<uint32_t> sizes;
    const XMLElement* vcount = child(primitive, "vcount");
    if (vcount == nullptr) {
      if (corners > 0) fail(primitive, "<polylist> has no <vcount>");
    } else {
      sizes = read_indices(vcount);
    }
    // A polygon of fewer than 3 corners is kept: the builder refuses it by its number and mesh repair drops it.
    uint64_t sum = 0;
    for (const uint32_t size : sizes) sum += size;
    if (sum != corners) {
      fail(p ? p : primitive, "<p> of <polylist> holds " + std::to_string(corners) +
                                  " corners, but <vcount> adds up to " + std::to_string(sum));
    }
    return sizes;
  }

  // <polygons>, <trifans>, <tristrips>: one polygon, fan or strip per <p>.
  void read_p_each(const XMLElement* primitive, const PrimitiveLayout& layout, PolygonMesh& mesh) const {
    const std::vector<const XMLElement*> ps = children(primitive, "p");
    if (const XMLElement* ph = child(primitive, "ph")) fail(ph, "polygons with holes (<ph>) are not supported");
    for (const XMLElement* p : ps) {
      const std::vector<uint32_t> indices = read_indices(p);
      const uint64_t corners = corner_count(p, layout, indices);
      // A polygon of fewer than 3 corners is kept, as in a <polylist>; a fan or a strip needs 3 to hold a triangle.
      if (corners < 3 && layout.kind != "polygons") {
        fail(p, "<p> of <" + layout.kind + "> has " + std::to_string(corners) + " corners; at least 3 are needed");
      }
      if (layout.kind == "polygons") {
        add_polygons(p, indices, layout.stride, layout.vertex_offset, {static_cast<uint32_t>(corners)}, mesh);
      } else {
        add_corner_triangles(p, indices, layout.stride, layout.vertex_offset,
                             fan_or_strip_triangles(layout.kind, corners), layout.kind == "tristrips", mesh);
      }
    }
    const char* noun = layout.kind == "polygons" ? "polygons" : layout.kind == "trifans" ? "fans" : "strips";
    check_count(primitive, layout, ps.size(), noun);
  }

  // The corners of the triangles a fan or a strip of `corners` corners makes, three by three; a strip's odd triangles
  // keep the strip's winding.
  static std::vector<uint32_t> fan_or_strip_triangles(const std::string& kind, uint64_t corners) {
    std::vector<uint32_t> triangle_corners;
    for (uint64_t i = 0; i + 2 < corners; ++i) {
      uint64_t a = i, b = i + 1, c = i + 2;
      if (kind == "trifans") {
        a = 0;
      } else if (i % 2 == 1) {
        std::swap(a, b);
      }
      triangle_corners.insert(triangle_corners.end(),
                              {static_cast<uint32_t>(a), static_cast<uint32_t>(b), static_cast<uint32_t>(c)});
    }
    return triangle_corners;
  }

  // ---- corners -------------------------------------------------------------------------------------

  // The vertex index of corner `c`, checked against the positions.
  uint32_t vertex_of(const XMLElement* p, const std::vector<uint32_t>& indices, uint64_t stride, uint64_t offset,
                     uint64_t c, const PolygonMesh& mesh) const {
    const uint64_t at = c * stride + offset;
    const uint32_t v = indices[at];
    if (v >= mesh.positions.size()) {
      fail(line_of_number(p, at), "<p> of <" + std::string(local_name(p->Parent()->ToElement())) +
                                      "> refers to vertex " + std::to_string(v) + ", but the positions hold only " +
                                      std::to_string(mesh.positions.size()));
    }
    return v;
  }

  void reserve_corners(const XMLElement* p, const PolygonMesh& mesh, uint64_t more) const {
    if (mesh.indices.size() + more > kMaxCorners) {
      fail(p, "more than " + std::to_string(kMaxCorners) + " polygon corners");
    }
  }

  void add_polygons(const XMLElement* p, const std::vector<uint32_t>& indices, uint64_t stride, uint64_t offset,
                    const std::vector<uint32_t>& sizes, PolygonMesh& mesh) const {
    if (sizes.empty()) return;  // an empty primitive may have no <p> at all
    reserve_corners(p, mesh, indices.size() / stride);
    std::vector<uint32_t> face;
    uint64_t corner = 0;
    for (uint32_t size : sizes) {
      face.clear();
      for (uint32_t k = 0; k < size; ++k) face.push_back(vertex_of(p, indices, stride, offset, corner++, mesh));
      mesh.add_face(face);
    }
  }

  void add_corner_triangles(const XMLElement* p, const std::vector<uint32_t>& indices, uint64_t stride, uint64_t offset,
                            const std::vector<uint32_t>& corners, bool drop_degenerate, PolygonMesh& mesh) const {
    reserve_corners(p, mesh, corners.size());
    for (size_t t = 0; t + 2 < corners.size(); t += 3) {
      const uint32_t a = vertex_of(p, indices, stride, offset, corners[t], mesh);
      const uint32_t b = vertex_of(p, indices, stride, offset, corners[t + 1], mesh);
      const uint32_t c = vertex_of(p, indices, stride, offset, corners[t + 2], mesh);
      if (drop_degenerate && (a == b || b == c || a == c)) continue;
      mesh.add_face({a, b, c});
    }
  }

  // ---- scene ---------------------------------------------------------------------------------------

  const XMLElement* chosen_scene(const XMLElement* root) const {
    std::vector<const XMLElement*> scenes;
    for (const XMLElement* library : children(root, "library_visual_scenes")) {
      for (const XMLElement* scene : children(library, "visual_scene")) scenes.push_back(scene);
    }
    const XMLElement* instance = child(child(root, "scene"), "instance_visual_scene");
    if (instance == nullptr) return scenes.empty() ? nullptr : scenes.front();
    const std::string url = required_attribute(instance, "url");
    for (const XMLElement* scene : scenes) {
      const char* id = scene->Attribute("id");
      if (id != nullptr && url == "#" + std::string(id)) return scene;
    }
    fail(instance, "<instance_visual_scene> refers to " + quote(url) + ", which is not a <visual_scene>");
  }

  // The node's own transform elements, in document order, composed onto `parent`.
  NodeTransform compose(const XMLElement* node, const NodeTransform& parent) const {
    NodeTransform out = parent;
    for (const XMLElement* e = node->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      const std::string_view kind = local_name(e);
      size_t expected = 0;
      if (kind == "matrix") {
        expected = 16;
      } else if (kind == "translate" || kind == "scale") {
        expected = 3;
      } else if (kind == "rotate") {
        expected = 4;
      } else if (kind == "lookat" || kind == "skew") {
        if (out.problem_at == nullptr) {
          out.problem_at = e;
          out.problem = tag(e) + " transforms are not supported";
        }
        continue;
      } else {
        continue;
      }
      const std::vector<double> v = read_reals(e);
      if (v.size() != expected) {
        fail(e, tag(e) + " holds " + std::to_string(v.size()) + " numbers, expected " + std::to_string(expected));
      }
      glm::dmat4 local(1.0);
      if (kind == "matrix") {
        for (int row = 0; row < 4; ++row) {
          for (int col = 0; col < 4; ++col) local[col][row] = v[static_cast<size_t>(row * 4 + col)];
        }
      } else if (kind == "translate") {
        local = glm::translate(local, glm::dvec3(v[0], v[1], v[2]));
      } else if (kind == "scale") {
        local = glm::scale(local, glm::dvec3(v[0], v[1], v[2]));
      } else {
        const glm::dvec3 axis(v[0], v[1], v[2]);
        const double length = glm::length(axis);
        if (!(length > 0) || !std::isfinite(length)) {
          if (out.problem_at == nullptr) {
            out.problem_at = e;
            out.problem = "<rotate> has a zero-length axis";
          }
          continue;
        }
        local = glm::rotate(local, glm::radians(v[3]), axis / length);
      }
      out.matrix = out.matrix * local;
    }
    return out;
  }

  void collect_instances(const XMLElement* root, const std::unordered_map<std::string, size_t>& geometry_by_id,
                         std::vector<std::vector<Instance>>& instances) const {
    const XMLElement* scene = chosen_scene(root);
    if (scene == nullptr) return;
    std::vector<std::pair<const XMLElement*, NodeTransform>> stack;
    const auto push_children = [&](const XMLElement* parent, const NodeTransform& transform) {
      const std::vector<const XMLElement*> nodes = children(parent, "node");
      for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) stack.emplace_back(*it, transform);
    };
    push_children(scene, NodeTransform{});
    while (!stack.empty()) {
      const auto [node, parent] = std::move(stack.back());
      stack.pop_back();
      const NodeTransform transform = compose(node, parent);
      for (const XMLElement* instance : children(node, "instance_geometry")) {
        const std::string url = required_attribute(instance, "url");
        const auto found = url.size() > 1 && url[0] == '#' ? geometry_by_id.find(url.substr(1)) : geometry_by_id.end();
        if (found == geometry_by_id.end()) {
          fail(instance, "<instance_geometry> refers to " + quote(url) + ", which is not a <geometry>");
        }
        if (transform.problem_at != nullptr) fail(transform.problem_at, transform.problem);
        instances[found->second].push_back({transform, instance});
      }
      push_children(node, transform);
    }
  }

  PolygonMesh transformed(const PolygonMesh& mesh, const Instance& instance, const XMLElement* geometry) const {
    PolygonMesh out = mesh;
    const glm::dmat4& m = instance.transform.matrix;
    for (size_t v = 0; v < out.positions.size(); ++v) {
      const glm::dvec3 p = glm::dvec3(m * glm::dvec4(out.positions[v], 1.0));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        fail(instance.element, "the node's transform moves vertex " + std::to_string(v) + " of <geometry id=" +
                                   quote(geometry->Attribute("id") ? geometry->Attribute("id") : "") +
                                   "> to a non-finite position");
      }
      out.positions[v] = p;
    }
    if (glm::determinant(glm::dmat3(m)) < 0) {
      for (size_t f = 0; f < out.num_faces(); ++f) {
        std::reverse(out.indices.begin() + out.face_offsets[f], out.indices.begin() + out.face_offsets[f + 1]);
      }
    }
    return out;
  }

  void append(PolygonMesh& out, const PolygonMesh& mesh, const XMLElement* at) const {
    if (out.positions.size() + mesh.positions.size() > kMaxVertices ||
        out.indices.size() + mesh.indices.size() > kMaxCorners) {
      fail(at, "the scene holds more than " + std::to_string(kMaxVertices) + " vertices or " +
                   std::to_string(kMaxCorners) + " polygon corners");
    }
    out.append(mesh);
  }

  std::string_view text_;
  std::string file_;
};

}  // namespace

// ---- entry points ----------------------------------------------------------------------------------

DaeFile parse_dae_file(std::string_view text, const std::string& name) { return DaeReader(text, name).read(); }

DaeFile read_dae_file(const std::filesystem::path& path) { return parse_dae_file(read_file(path), path.string()); }

PolygonMesh parse_dae(std::string_view text, const std::string& name) { return parse_dae_file(text, name).mesh; }

PolygonMesh read_dae(const std::filesystem::path& path) { return read_dae_file(path).mesh; }

}  // namespace meshedit
