// glTF reading (see gltf_io.h). tinygltf parses the JSON and the buffers; everything it hands over is
// distrusted: indices into model arrays, offsets, lengths, strides and counts are all checked here,
// with 64-bit arithmetic, before a single byte of a buffer is read.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   loading through tinygltf         the file callbacks (FilePolicy, read_whole_file, refuse_write, skip_image),
//                                    load_model
//   turning the model into polygons  component_size, read_unsigned; GltfMeshBuilder::build
//   nodes                            walk_nodes, local_transform
//   meshes                           add_mesh: each primitive's triangles, placed by its node
//   accessors                        accessor, view_bytes, locate, apply_sparse, read_positions, read_indices
//   entry points                     parse_gltf, parse_glb, read_gltf
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>
#include <vector>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "core/file_bytes.h"
#include "core/finite.h"
#include "io/file_access.h"
#include "io/file_error.h"
#include "io/gltf_io.h"
#include "io/io_limits.h"

namespace meshedit {
namespace {

// ---- loading through tinygltf ------------------------------------------------------------------------

struct FilePolicy {
  bool files_allowed = false;
};

// Says yes whenever reading could say why not, so the message comes from read_whole_file ("not a
// regular file", "cannot be read when parsing from memory") rather than tinygltf's "File not found".
bool file_exists(const std::string& path, void* user) {
  const auto* policy = static_cast<const FilePolicy*>(user);
  std::error_code ec;
  return !policy->files_allowed || std::filesystem::exists(path, ec);
}

// tinygltf's default expands "~" and variables; a file name in a glTF file is only a file name.
std::string keep_path(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto* policy = static_cast<const FilePolicy*>(user);
  if (!policy->files_allowed) {
    if (err) *err += "external files cannot be read when parsing from memory\n";
    return false;
  }
  try {
    const std::string bytes = read_file(path);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const FileError& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not allowed while reading\n";
  return false;
}

// Images are never decoded: MeshEdit draws geometry only.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '\r')) text.pop_back();
  for (char& c : text) {
    if (c == '\n') c = ' ';
  }
  return text;
}

tinygltf::Model load_model(std::string_view bytes, const std::string& name, const std::filesystem::path& base_dir,
                           bool binary) {
  if (bytes.empty()) throw FileError(name, "", "file is empty");
  if (bytes.size() > kMaxReadFileBytes) throw FileError(name, "", "file is too large");
  FilePolicy policy{!base_dir.empty()};
  tinygltf::TinyGLTF loader;
  // By name: tinygltf 2.8 (Ubuntu 24.04) has a member more (GetFileSizeInBytes, left empty: it is optional).
  tinygltf::FsCallbacks callbacks{};
  callbacks.FileExists = &file_exists;
  callbacks.ExpandFilePath = &keep_path;
  callbacks.ReadWholeFile = &read_whole_file;
  callbacks.WriteWholeFile = &refuse_write;
  callbacks.user_data = &policy;
  loader.SetFsCallbacks(callbacks);
  loader.SetImageLoader(&skip_image, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    const auto size = static_cast<unsigned int>(bytes.size());
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                              size, base_dir.string())
                : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, base_dir.string());
  } catch (const std::exception& e) {
    throw FileError(name, "", std::string("not a valid glTF file: ") + e.what());
  }
  if (!ok) throw FileError(name, "", err.empty() ? "not a valid glTF file" : trimmed(err));
  return model;
}

// ---- turning the model into polygons ---------------------------------------------------------------------

size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return 4;
    default: return 0;  // not an index type
  }
}

uint32_t read_unsigned(const unsigned char* at, size_t size) {
  if (size == 1) return *at;
  if (size == 2) {
    uint16_t v;
    std::memcpy(&v, at, 2);
    return v;
  }
  uint32_t v;
  std::memcpy(&v, at, 4);
  return v;
}

std::string object(const char* kind, size_t index) { return std::string(kind) + " " + std::to_string(index); }

class GltfMeshBuilder {
 public:
  GltfMeshBuilder(const tinygltf::Model& model, const std::string& file) : model_(model), file_(file) {}

  PolygonMesh build() {
    if (model_.nodes.empty()) {
      for (size_t m = 0; m < model_.meshes.size(); ++m) add_mesh(m, glm::dmat4(1.0), "");
    } else {
      walk_nodes();
    }
    if (out_.num_faces() == 0) throw FileError(file_, "", "file holds no triangles");
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& place, const std::string& message) const {
    throw FileError(file_, place, message);
  }

  // ---- nodes ----

  void walk_nodes() {
    std::vector<int> roots;
    if (model_.defaultScene >= 0) {
      if (static_cast<size_t>(model_.defaultScene) >= model_.scenes.size()) {
        fail("scene", "default scene " + std::to_string(model_.defaultScene) + " does not exist");
      }
      roots = model_.scenes[static_cast<size_t>(model_.defaultScene)].nodes;
    } else {
      std::vector<bool> has_parent(model_.nodes.size(), false);
      for (size_t n = 0; n < model_.nodes.size(); ++n) {
        for (int c : model_.nodes[n].children) {
          if (c >= 0 && static_cast<size_t>(c) < model_.nodes.size()) has_parent[static_cast<size_t>(c)] = true;
        }
      }
      for (size_t n = 0; n < model_.nodes.size(); ++n) {
        if (!has_parent[n]) roots.push_back(static_cast<int>(n));
      }
    }
    std::vector<bool> visited(model_.nodes.size(), false);
    std::vector<std::pair<int, glm::dmat4>> stack;
    const auto push = [&](const std::vector<int>& nodes, const glm::dmat4& parent, const std::string& place) {
      for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
        if (*it < 0 || static_cast<size_t>(*it) >= model_.nodes.size()) {
          fail(place, "refers to node " + std::to_string(*it) + ", which does not exist");
        }
        stack.emplace_back(*it, parent);
      }
    };
    push(roots, glm::dmat4(1.0), "scene");
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      const auto n = static_cast<size_t>(index);
      const std::string place = object("node", n);
      if (visited[n]) fail(place, "is reached twice; glTF nodes must form a tree");
      visited[n] = true;
      const tinygltf::Node& node = model_.nodes[n];
      const glm::dmat4 world = parent * local_transform(node, place);
      if (node.mesh >= 0) {
        if (static_cast<size_t>(node.mesh) >= model_.meshes.size()) {
          fail(place, "refers to mesh " + std::to_string(node.mesh) + ", which does not exist");
        }
        add_mesh(static_cast<size_t>(node.mesh), world, place);
      }
      push(node.children, world, place);
    }
  }

  glm::dmat4 local_transform(const tinygltf::Node& node, const std::string& place) const {
    const auto check = [&](const std::vector<double>& v, size_t expected, const char* what) {
      if (!v.empty() && v.size() != expected) {
        fail(place,
             std::string(what) + " has " + std::to_string(v.size()) + " numbers, expected " + std::to_string(expected));
      }
      for (double x : v) {
        if (!std::isfinite(x)) fail(place, std::string(what) + " is not finite");
      }
    };
    check(node.matrix, 16, "matrix");
    check(node.translation, 3, "translation");
    check(node.rotation, 4, "rotation");
    check(node.scale, 3, "scale");
    glm::dmat4 m(1.0);
    if (!node.matrix.empty()) {
      for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) m[col][row] = node.matrix[static_cast<size_t>(col * 4 + row)];
      }
      return m;
    }
    if (!node.translation.empty()) {
      m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {
      glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      const double length = glm::length(q);
      if (!(length > 0) || !std::isfinite(length)) fail(place, "rotation is not a unit quaternion");
      m = m * glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
  }

  // ---- meshes ----

  // `node_place` names the node that instances the mesh ("" when the file has no nodes).
  void add_mesh(size_t mesh_index, const glm::dmat4& world, const std::string& node_place) {
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0;
    std::map<int, uint32_t> base_of_accessor;  // POSITION accessor -> first output vertex, this instance
    const tinygltf::Mesh& mesh = model_.meshes[mesh_index];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = mesh.primitives[p];
      const std::string place = object("mesh", mesh_index) + " primitive " + std::to_string(p);
      const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
      if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP ||
          mode == TINYGLTF_MODE_LINE_STRIP) {
        continue;
      }
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        fail(place, "unknown mode " + std::to_string(mode));
      }
      const auto found = primitive.attributes.find("POSITION");
      if (found == primitive.attributes.end()) fail(place, "has no POSITION attribute");
      const int position_accessor = found->second;

      auto cached = base_of_accessor.find(position_accessor);
      if (cached == base_of_accessor.end()) {
        std::vector<glm::dvec3> positions = read_positions(position_accessor, place);
        if (out_.positions.size() + positions.size() > kMaxVertices) {
          fail(place, "the scene holds more than " + std::to_string(kMaxVertices) + " vertices");
        }
        for (size_t v = 0; v < positions.size(); ++v) {
          const glm::dvec3 moved = glm::dvec3(world * glm::dvec4(positions[v], 1.0));
          if (!finite(moved)) {
            fail(place,
                 "the transform of " + node_place + " moves vertex " + std::to_string(v) + " to a non-finite position");
          }
          out_.positions.push_back(moved);
        }
        cached =
            base_of_accessor.emplace(position_accessor, static_cast<uint32_t>(out_.positions.size() - positions.size()))
                .first;
      }
      const uint32_t base = cached->second;
      const size_t accessor_count = model_.accessors[static_cast<size_t>(position_accessor)].count;

      std::vector<uint32_t> indices;
      if (primitive.indices >= 0) {
        indices = read_indices(primitive.indices, accessor_count, place);
      } else {
        indices.resize(accessor_count);
        for (size_t i = 0; i < accessor_count; ++i) indices[i] = static_cast<uint32_t>(i);
      }
      add_triangles(indices, mode, base, mirrored, place);
    }
  }

  void add_triangles(const std::vector<uint32_t>& indices, int mode, uint32_t base, bool mirrored,
                     const std::string& place) {
    const size_t n = indices.size();
    if (mode == TINYGLTF_MODE_TRIANGLES && n % 3 != 0) {
      fail(place, std::to_string(n) + " indices do not form whole triangles");
    }
    const size_t triangles = mode == TINYGLTF_MODE_TRIANGLES ? n / 3 : (n >= 3 ? n - 2 : 0);
    if (out_.indices.size() + 3 * triangles > kMaxCorners) {
      fail(place, "the scene holds more than " + std::to_string(kMaxCorners) + " triangle corners");
    }
    for (size_t t = 0; t < triangles; ++t) {
      uint32_t a, b, c;
      if (mode == TINYGLTF_MODE_TRIANGLES) {
        a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
      } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        a = indices[0], b = indices[t + 1], c = indices[t + 2];
      } else {
        a = indices[t], b = indices[t + 1], c = indices[t + 2];
        if (t % 2 == 1) std::swap(a, b);
        if (a == b || b == c || a == c) continue;  // a strip's stitching triangle
      }
      if (mirrored) std::swap(b, c);
      out_.add_face({base + a, base + b, base + c});
    }
  }

  // ---- accessors ----

  struct Elements {
    const unsigned char* base = nullptr;  // nullptr: the accessor has no buffer view (all zeros)
    size_t stride = 0;
  };

  const tinygltf::Accessor& accessor(int index, const std::string& place) const {
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size()) {
      fail(place, "refers to accessor " + std::to_string(index) + ", which does not exist");
    }
    return model_.accessors[static_cast<size_t>(index)];
  }

  // `bytes` bytes at `offset` inside buffer view `view_index`, checked against the view and its buffer.
  const unsigned char* view_bytes(int view_index, uint64_t offset, uint64_t bytes, const std::string& place) const {
    if (view_index < 0 || static_cast<size_t>(view_index) >= model_.bufferViews.size()) {
      fail(place, "refers to bufferView " + std::to_string(view_index) + ", which does not exist");
    }
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<size_t>(view_index)];
    const std::string view_place = object("bufferView", static_cast<size_t>(view_index));
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size()) {
      fail(view_place, "refers to buffer " + std::to_string(view.buffer) + ", which does not exist");
    }
    const std::vector<unsigned char>& data = model_.buffers[static_cast<size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
      fail(view_place, "bytes " + std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                           " exceed buffer " + std::to_string(view.buffer) + " of " + std::to_string(data.size()) +
                           " bytes");
    }
    if (offset > view.byteLength || bytes > view.byteLength - offset) {
      fail(place, "reads bytes " + std::to_string(offset) + " + " + std::to_string(bytes) + ", beyond the " +
                      std::to_string(view.byteLength) + " bytes of bufferView " + std::to_string(view_index));
    }
    return data.data() + view.byteOffset + offset;
  }

  Elements locate(const tinygltf::Accessor& a, size_t element_size, const std::string& place) const {
    if (a.bufferView < 0) return {};
    if (static_cast<size_t>(a.bufferView) >= model_.bufferViews.size()) {
      fail(place, "refers to bufferView " + std::to_string(a.bufferView) + ", which does not exist");
    }
    const size_t byte_stride = model_.bufferViews[static_cast<size_t>(a.bufferView)].byteStride;
    if (byte_stride != 0 && (byte_stride < element_size || byte_stride > 252)) {
      fail(place, "byteStride " + std::to_string(byte_stride) + " of bufferView " + std::to_string(a.bufferView) +
                      " does not fit elements of " + std::to_string(element_size) + " bytes");
    }
    const size_t stride = byte_stride != 0 ? byte_stride : element_size;
    // a.count is already limited (<= kMaxCorners), so this cannot overflow.
    const uint64_t span = a.count == 0 ? 0 : (uint64_t(a.count) - 1) * stride + element_size;
    return {view_bytes(a.bufferView, a.byteOffset, span, place), stride};
  }

  // Calls `apply(element_index, bytes)` for each sparse substitute of a sparse accessor.
  template <class Apply>
  void apply_sparse(const tinygltf::Accessor& a, size_t element_size, const std::string& place, Apply apply) const {
    if (!a.sparse.isSparse) return;
    const auto& sparse = a.sparse;
    if (sparse.count < 1 || static_cast<size_t>(sparse.count) > a.count) {
      fail(place, "sparse count " + std::to_string(sparse.count) + " must be from 1 to the accessor count " +
                      std::to_string(a.count));
    }
    const size_t index_size = component_size(sparse.indices.componentType);
    if (index_size == 0) fail(place, "sparse indices must be unsigned byte, short or int");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) fail(place, "sparse byteOffset is negative");
    const auto count = static_cast<uint64_t>(sparse.count);
    const unsigned char* indices =
        view_bytes(sparse.indices.bufferView, static_cast<uint64_t>(sparse.indices.byteOffset), count * index_size,
                   place + " sparse indices");
    const unsigned char* values = view_bytes(sparse.values.bufferView, static_cast<uint64_t>(sparse.values.byteOffset),
                                             count * element_size, place + " sparse values");
    for (uint64_t i = 0; i < count; ++i) {
      const uint32_t target = read_unsigned(indices + i * index_size, index_size);
      if (target >= a.count) {
        fail(place,
             "sparse index " + std::to_string(target) + " is beyond the accessor count " + std::to_string(a.count));
      }
      apply(target, values + i * element_size);
    }
  }

  std::vector<glm::dvec3> read_positions(int index, const std::string& primitive_place) const {
    const tinygltf::Accessor& a = accessor(index, primitive_place);
    const std::string place = object("accessor", static_cast<size_t>(index));
    if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
      fail(place, "POSITION must be a float VEC3 accessor");
    }
    // Without a buffer view the accessor is zeros plus sparse values: nothing in the file bounds its
    // count, so allow fewer.
    const size_t limit = a.bufferView < 0 ? (size_t(1) << 20) : kMaxVertices;
    if (a.count > limit) fail(place, "count " + std::to_string(a.count) + " is too large for POSITION");
    const Elements elements = locate(a, 12, place);
    std::vector<glm::dvec3> positions(a.count, glm::dvec3(0.0));
    const auto decode = [](const unsigned char* at) {
      float xyz[3];
      std::memcpy(xyz, at, sizeof xyz);
      return glm::dvec3(xyz[0], xyz[1], xyz[2]);
    };
    if (elements.base != nullptr) {
      for (size_t i = 0; i < a.count; ++i) positions[i] = decode(elements.base + i * elements.stride);
    }
    apply_sparse(a, 12, place, [&](uint32_t i, const unsigned char* at) { positions[i] = decode(at); });
    for (size_t i = 0; i < positions.size(); ++i) {
      if (!finite(positions[i])) fail(place, "position " + std::to_string(i) + " is not finite");
    }
    return positions;
  }

  std::vector<uint32_t> read_indices(int index, size_t vertex_count, const std::string& primitive_place) const {
    const tinygltf::Accessor& a = accessor(index, primitive_place);
    const std::string place = object("accessor", static_cast<size_t>(index));
    const size_t size = component_size(a.componentType);
    if (a.type != TINYGLTF_TYPE_SCALAR || size == 0) {
      fail(place, "indices must be an unsigned byte, short or int SCALAR accessor");
    }
    const size_t limit = a.bufferView < 0 ? (size_t(1) << 20) : kMaxCorners;
    if (a.count > limit) fail(place, "count " + std::to_string(a.count) + " is too large for indices");
    const Elements elements = locate(a, size, place);
    std::vector<uint32_t> indices(a.count, 0);
    if (elements.base != nullptr) {
      for (size_t i = 0; i < a.count; ++i) indices[i] = read_unsigned(elements.base + i * elements.stride, size);
    }
    apply_sparse(a, size, place, [&](uint32_t i, const unsigned char* at) { indices[i] = read_unsigned(at, size); });
    for (size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] >= vertex_count) {
        fail(place, "index " + std::to_string(i) + " refers to vertex " + std::to_string(indices[i]) +
                        ", but the POSITION accessor has only " + std::to_string(vertex_count));
      }
    }
    return indices;
  }

  const tinygltf::Model& model_;
  const std::string& file_;
  PolygonMesh out_;
};

bool starts_with_glb_magic(std::string_view bytes) { return bytes.size() >= 4 && bytes.substr(0, 4) == "glTF"; }

}  // namespace

// ---- entry points ----------------------------------------------------------------------------------

PolygonMesh parse_gltf(std::string_view json, const std::string& name, const std::filesystem::path& base_dir) {
  return GltfMeshBuilder(load_model(json, name, base_dir, false), name).build();
}

PolygonMesh parse_glb(std::string_view bytes, const std::string& name, const std::filesystem::path& base_dir) {
  return GltfMeshBuilder(load_model(bytes, name, base_dir, true), name).build();
}

PolygonMesh read_gltf(const std::filesystem::path& path) {
  const std::string bytes = read_file(path);
  std::filesystem::path base_dir = path.parent_path();
  if (base_dir.empty()) base_dir = ".";
  return starts_with_glb_magic(bytes) ? parse_glb(bytes, path.string(), base_dir)
                                      : parse_gltf(bytes, path.string(), base_dir);
}

}  // namespace meshedit
