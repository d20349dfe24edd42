// What the CBOR texts of a call to another copy of the program share (exercise/student_call_text.h,
// writeup/writeup_text.h): points, elements and meshes as JSON values, and reading bytes as a text of one format.
// Included by those sources only (it brings nlohmann-json, which both link).
//
// Invariants:
// - A point is [x, y, z] with its doubles' bits kept; an element [kind, index], its kind kept even when null; a mesh
//   its records (core/mesh_records.h), so every id and a broken mesh come back as they were.
// - read_cbor_text throws std::runtime_error "not a WHAT: ..." for bytes that are not CBOR, not of the format, or whose
//   `read` throws (a missing field); std::bad_alloc passes through.
#pragma once

#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "core/halfedge_mesh.h"
#include "core/mesh_records.h"

namespace meshedit::cbor {

inline nlohmann::json point_json(const glm::dvec3& p) { return nlohmann::json::array({p.x, p.y, p.z}); }

inline glm::dvec3 point_from(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 3) throw std::runtime_error("a point is not 3 numbers");
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

inline nlohmann::json points_json(const std::vector<glm::dvec3>& points) {
  nlohmann::json j = nlohmann::json::array();
  for (const glm::dvec3& p : points) j.push_back(point_json(p));
  return j;
}

inline std::vector<glm::dvec3> points_from(const nlohmann::json& j) {
  std::vector<glm::dvec3> points;
  for (const nlohmann::json& p : j) points.push_back(point_from(p));
  return points;
}

inline nlohmann::json element_json(ElementRef element) {
  return nlohmann::json::array({static_cast<int>(element.kind), element.index});
}

inline ElementRef element_from(const nlohmann::json& j) {
  const int kind = j.at(0).get<int>();
  if (kind < 0 || kind > static_cast<int>(ElementKind::Boundary)) throw std::runtime_error("an element of no kind");
  return {static_cast<ElementKind>(kind), j.at(1).get<uint32_t>()};
}

inline nlohmann::json mesh_json(const HalfedgeMesh* mesh) {
  return mesh ? nlohmann::json(format_mesh_records(*mesh)) : nlohmann::json(nullptr);
}

// A MeshError (records that do not parse) is a std::runtime_error already.
inline std::shared_ptr<HalfedgeMesh> mesh_from(const nlohmann::json& j, const std::string& name) {
  if (j.is_null()) return nullptr;
  return std::make_shared<HalfedgeMesh>(parse_mesh_records(j.get<std::string>(), name));
}

// The CBOR read as a text of `format` (its "format" field) by `read`.
template <typename Read>
auto read_cbor_text(std::span<const uint8_t> bytes, const char* format, const char* what, Read read) {
  try {
    const nlohmann::json j = nlohmann::json::from_cbor(bytes.begin(), bytes.end());
    if (!j.is_object() || j.value("format", "") != format) throw std::runtime_error("it is not one");
    return read(j);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("not a ") + what + ": " + e.what());
  }
}

}  // namespace meshedit::cbor
