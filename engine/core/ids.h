// Typed element ids for the half-edge mesh and the one formatter that prints them everywhere.
//
// Invariants:
// - An id is an index into its kind's arrays; ids are never reused within a mesh's lifetime.
// - `kInvalidIndex` means "no element" (a null pointer in the course code).
// - Faces and boundary loops share the FaceId type: a boundary loop carries kBoundaryBit, so
//   `f.is_boundary()` needs no mesh, and it prints as `b0`, `b1`... while real faces print `f0`...
// - The printed forms are `v12 h37 e5 f3 b0`; `parse_element` reads exactly what `format_id` writes.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace meshedit {

inline constexpr uint32_t kInvalidIndex = 0xFFFFFFFFu;

enum class ElementKind : uint8_t { Vertex, Halfedge, Edge, Face, Boundary };
// How many kinds there are: the size of every array indexed by ElementKind. Boundary stays the last kind.
inline constexpr int kElementKindCount = static_cast<int>(ElementKind::Boundary) + 1;

// Singular lower-case noun for messages: "vertex", "halfedge", "edge", "face", "boundary".
const char* kind_name(ElementKind kind);
// The one-letter prefix of printed ids: 'v', 'h', 'e', 'f', 'b'.
char kind_prefix(ElementKind kind);

template <ElementKind K>
struct Id {
  uint32_t index = kInvalidIndex;

  constexpr Id() = default;
  constexpr explicit Id(uint32_t i) : index(i) {}
  constexpr bool valid() const { return index != kInvalidIndex; }
  constexpr explicit operator bool() const { return valid(); }
  friend constexpr bool operator==(Id a, Id b) { return a.index == b.index; }
  friend constexpr bool operator!=(Id a, Id b) { return a.index != b.index; }
  friend constexpr bool operator<(Id a, Id b) { return a.index < b.index; }
};

using VertexId = Id<ElementKind::Vertex>;
using HalfedgeId = Id<ElementKind::Halfedge>;
using EdgeId = Id<ElementKind::Edge>;

// A face or a boundary loop. The top bit tells which; `slot()` is the index into its own array.
struct FaceId {
  static constexpr uint32_t kBoundaryBit = 0x80000000u;
  uint32_t index = kInvalidIndex;

  constexpr FaceId() = default;
  constexpr explicit FaceId(uint32_t raw) : index(raw) {}
  static constexpr FaceId face(uint32_t slot) { return FaceId(slot); }
  static constexpr FaceId boundary(uint32_t slot) { return FaceId(slot | kBoundaryBit); }

  constexpr bool valid() const { return index != kInvalidIndex; }
  constexpr explicit operator bool() const { return valid(); }
  constexpr bool is_boundary() const { return valid() && (index & kBoundaryBit) != 0; }
  constexpr uint32_t slot() const { return index & ~kBoundaryBit; }
  constexpr ElementKind kind() const { return is_boundary() ? ElementKind::Boundary : ElementKind::Face; }
  friend constexpr bool operator==(FaceId a, FaceId b) { return a.index == b.index; }
  friend constexpr bool operator!=(FaceId a, FaceId b) { return a.index != b.index; }
  friend constexpr bool operator<(FaceId a, FaceId b) { return a.index < b.index; }
};

// Any element: what selections, validation reports and diffs refer to.
// For faces and boundaries `index` is the slot (without the boundary bit).
struct ElementRef {
  ElementKind kind = ElementKind::Vertex;
  uint32_t index = kInvalidIndex;

  constexpr ElementRef() = default;
  constexpr ElementRef(ElementKind k, uint32_t i) : kind(k), index(i) {}
  constexpr ElementRef(VertexId v) : kind(ElementKind::Vertex), index(v.index) {}
  constexpr ElementRef(HalfedgeId h) : kind(ElementKind::Halfedge), index(h.index) {}
  constexpr ElementRef(EdgeId e) : kind(ElementKind::Edge), index(e.index) {}
  constexpr ElementRef(FaceId f) : kind(f.kind()), index(f.valid() ? f.slot() : kInvalidIndex) {}

  constexpr bool valid() const { return index != kInvalidIndex; }
  // Back to a FaceId; only meaningful for Face and Boundary kinds.
  constexpr FaceId face_id() const {
    return kind == ElementKind::Boundary ? FaceId::boundary(index) : FaceId::face(index);
  }
  friend constexpr bool operator==(ElementRef a, ElementRef b) { return a.kind == b.kind && a.index == b.index; }
  friend constexpr bool operator!=(ElementRef a, ElementRef b) { return !(a == b); }
  friend constexpr bool operator<(ElementRef a, ElementRef b) {
    return a.kind != b.kind ? a.kind < b.kind : a.index < b.index;
  }
};

// `v12`, `h37`, `e5`, `f3`, `b0`; an invalid id prints as `-` (a null pointer).
std::string format_id(ElementRef element);
// Parses what format_id prints (`h37`); nullopt for anything else.
std::optional<ElementRef> parse_element(std::string_view text);

}  // namespace meshedit

template <meshedit::ElementKind K>
struct std::hash<meshedit::Id<K>> {
  size_t operator()(meshedit::Id<K> id) const noexcept { return std::hash<uint32_t>{}(id.index); }
};
template <>
struct std::hash<meshedit::FaceId> {
  size_t operator()(meshedit::FaceId id) const noexcept { return std::hash<uint32_t>{}(id.index); }
};
template <>
struct std::hash<meshedit::ElementRef> {
  size_t operator()(meshedit::ElementRef r) const noexcept {
    return std::hash<uint64_t>{}((uint64_t(r.kind) << 32) | r.index);
  }
};
