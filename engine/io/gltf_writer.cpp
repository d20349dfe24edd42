// glTF writing (see gltf_io.h): one buffer holding float32 positions then uint32 indices (both 4-byte
// aligned, as the specification requires), two buffer views, two accessors, one mesh, one node, one
// scene. tinygltf serialises it; a .gltf gets the buffer as a data URI, a .glb as its binary chunk.
#include <cfloat>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

#include <tiny_gltf.h>

#include "io/file_access.h"
#include "io/file_error.h"
#include "io/gltf_io.h"
#include "io/polygon_checks.h"

namespace meshedit {
namespace {

tinygltf::Model make_model(const PolygonMesh& mesh, const std::string& name) {
  require_writable(mesh, name);
  std::vector<float> positions;
  positions.reserve(mesh.positions.size() * 3);
  std::vector<double> min(3, 0.0), max(3, 0.0);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      const double value = mesh.positions[v][axis];
      if (std::abs(value) > FLT_MAX) {
        throw FileError(name, "vertex " + std::to_string(v), "coordinate does not fit a 32-bit float");
      }
      const auto stored = static_cast<float>(value);
      positions.push_back(stored);
      // min/max must describe the stored (rounded) values.
      if (v == 0 || stored < min[axis]) min[axis] = stored;
      if (v == 0 || stored > max[axis]) max[axis] = stored;
    }
  }
  std::vector<uint32_t> indices;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const auto face = mesh.face(f);
    for (size_t i = 1; i + 1 < face.size(); ++i) indices.insert(indices.end(), {face[0], face[i], face[i + 1]});
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "MeshEdit";
  tinygltf::Buffer buffer;
  const size_t position_bytes = positions.size() * sizeof(float);
  const size_t index_bytes = indices.size() * sizeof(uint32_t);
  buffer.data.resize(position_bytes + index_bytes);
  std::memcpy(buffer.data.data(), positions.data(), position_bytes);
  std::memcpy(buffer.data.data() + position_bytes, indices.data(), index_bytes);
  model.buffers.push_back(std::move(buffer));

  tinygltf::BufferView position_view;
  position_view.buffer = 0;
  position_view.byteOffset = 0;
  position_view.byteLength = position_bytes;
  position_view.target = TINYGLTF_TARGET_ARRAY_BUFFER;
  tinygltf::BufferView index_view;
  index_view.buffer = 0;
  index_view.byteOffset = position_bytes;
  index_view.byteLength = index_bytes;
  index_view.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
  model.bufferViews = {position_view, index_view};

  tinygltf::Accessor position_accessor;
  position_accessor.bufferView = 0;
  position_accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  position_accessor.count = mesh.positions.size();
  position_accessor.type = TINYGLTF_TYPE_VEC3;
  position_accessor.minValues = min;
  position_accessor.maxValues = max;
  tinygltf::Accessor index_accessor;
  index_accessor.bufferView = 1;
  index_accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  index_accessor.count = indices.size();
  index_accessor.type = TINYGLTF_TYPE_SCALAR;
  model.accessors = {position_accessor, index_accessor};

  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = 0;
  primitive.indices = 1;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh gltf_mesh;
  gltf_mesh.primitives.push_back(primitive);
  model.meshes.push_back(gltf_mesh);

  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

std::string serialise(const PolygonMesh& mesh, const std::string& name, bool binary) {
  tinygltf::Model model = make_model(mesh, name);  // not const: tinygltf 2.5 (Ubuntu 22.04) takes a Model*
  tinygltf::TinyGLTF writer;
  std::ostringstream stream;
  if (!writer.WriteGltfSceneToStream(&model, stream, !binary, binary)) {
    throw FileError(name, "", "tinygltf could not serialise the mesh");
  }
  return stream.str();
}

}  // namespace

std::string format_gltf(const PolygonMesh& mesh, const std::string& name) { return serialise(mesh, name, false); }

std::string format_glb(const PolygonMesh& mesh, const std::string& name) { return serialise(mesh, name, true); }

void write_gltf(const std::filesystem::path& path, const PolygonMesh& mesh) {
  write_file(path, format_gltf(mesh, path.string()));
}

void write_glb(const std::filesystem::path& path, const PolygonMesh& mesh) {
  write_file(path, format_glb(mesh, path.string()));
}

}  // namespace meshedit
