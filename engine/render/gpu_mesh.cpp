// GPU buffers of the slot layout and their in-place updates (see gpu_mesh.h).
#include "render/gpu_mesh.h"

#include <algorithm>
#include <array>

namespace meshedit::gl {
namespace {

// Calls write(first_slot, values) once per run of consecutive slots of `items` (sorted by slot).
template <class Item, class Value, class Get, class Write>
void for_each_run(const std::vector<Item>& items, Get&& get, Write&& write) {
  std::vector<Value> run;
  size_t i = 0;
  while (i < items.size()) {
    const uint32_t first = items[i].first;
    run.clear();
    size_t j = i;
    while (j < items.size() && items[j].first == first + (j - i)) run.push_back(get(items[j++]));
    write(first, run);
    i = j;
  }
}

}  // namespace

GpuMesh::GpuMesh()
    : face_vao_(make_vertex_array()),
      extra_vao_(make_vertex_array()),
      positions_(make_buffer()),
      normals_(make_buffer()),
      triangles_(make_buffer()),
      extra_triangles_(make_buffer()) {
  for (GLuint vao : {face_vao_.get(), extra_vao_.get()}) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, positions_.get());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, normals_.get());
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vao == face_vao_.get() ? triangles_.get() : extra_triangles_.get());
  }
  glBindVertexArray(0);
  if (!kHasPrimitiveId) pull_ = std::make_unique<Pull>();
}

void GpuMesh::upload(const SlotGeometry& g) {
  const size_t vertices = g.positions.size(), faces = g.face_normals.size(), edge_count = g.edges.size();
  vertex_slots_ = with_headroom(vertices);
  face_slots_ = with_headroom(faces);
  allocate_buffer(GL_ARRAY_BUFFER, positions_.get(), vertex_slots_ * sizeof(glm::vec3), g.positions.data(),
                  vertices * sizeof(glm::vec3));
  allocate_buffer(GL_ARRAY_BUFFER, normals_.get(), vertex_slots_ * sizeof(glm::vec3), g.smooth_normals.data(),
                  vertices * sizeof(glm::vec3));
  glBindVertexArray(face_vao_.get());
  allocate_buffer(GL_ELEMENT_ARRAY_BUFFER, triangles_.get(), face_slots_ * 3 * sizeof(uint32_t), g.triangles.data(),
                  g.triangles.size() * sizeof(uint32_t));
  glBindVertexArray(extra_vao_.get());
  allocate_buffer(GL_ELEMENT_ARRAY_BUFFER, extra_triangles_.get(), g.extra_triangles.size() * sizeof(uint32_t),
                  g.extra_triangles.data(), g.extra_triangles.size() * sizeof(uint32_t));
  glBindVertexArray(0);
  if (pull_) {
    pull_->positions.allocate(vertex_slots_ * sizeof(glm::vec3), g.positions.data(), vertices * sizeof(glm::vec3));
    pull_->normals.allocate(vertex_slots_ * sizeof(glm::vec3), g.smooth_normals.data(), vertices * sizeof(glm::vec3));
    pull_->corners.allocate(face_slots_ * 3 * sizeof(uint32_t), g.triangles.data(),
                            g.triangles.size() * sizeof(uint32_t));
    pull_->extra_corners.allocate(g.extra_triangles.size() * sizeof(uint32_t), g.extra_triangles.data(),
                                  g.extra_triangles.size() * sizeof(uint32_t));
  }
  extra_faces_.allocate(g.extra_faces.size() * sizeof(uint32_t), g.extra_faces.data(),
                        g.extra_faces.size() * sizeof(uint32_t));
  face_normals.allocate(face_slots_ * sizeof(glm::vec4), g.face_normals.data(), faces * sizeof(glm::vec4));
  points.allocate(g.points.data(), vertices, vertex_slots_);
  edges.allocate(g.edges.data(), edge_count, with_headroom(edge_count));
  std::vector<EdgeSegment> boundary;
  boundary.reserve(g.boundary_edges.size());
  for (uint32_t e : g.boundary_edges) boundary.push_back(g.edges[e]);
  boundary_edges.upload(boundary.data(), boundary.size(), GL_DYNAMIC_DRAW);
  face_count_ = faces;
  extra_count_ = g.extra_faces.size();
}

bool GpuMesh::fits(const SlotPatch& p) const {
  return p.vertex_capacity <= vertex_slots_ && p.face_capacity <= face_slots_ && p.edge_capacity <= edges.capacity();
}

void GpuMesh::apply(const SlotPatch& p) {
  using Point = std::pair<uint32_t, VertexPoint>;
  for_each_run<Point, VertexPoint>(
      p.points, [](const Point& x) { return x.second; },
      [&](uint32_t first, const std::vector<VertexPoint>& run) {
        points.write(first, run.data(), run.size());
        std::vector<glm::vec3> positions(run.size());
        for (size_t i = 0; i < run.size(); ++i) positions[i] = run[i].position;
        write_buffer(GL_ARRAY_BUFFER, positions_.get(), first * sizeof(glm::vec3), positions.data(),
                     positions.size() * sizeof(glm::vec3));
        if (pull_) {
          pull_->positions.write(first * sizeof(glm::vec3), positions.data(), positions.size() * sizeof(glm::vec3));
        }
      });
  using Normal = std::pair<uint32_t, glm::vec3>;
  for_each_run<Normal, glm::vec3>(
      p.normals, [](const Normal& x) { return x.second; },
      [&](uint32_t first, const std::vector<glm::vec3>& run) {
        write_buffer(GL_ARRAY_BUFFER, normals_.get(), first * sizeof(glm::vec3), run.data(),
                     run.size() * sizeof(glm::vec3));
        if (pull_) pull_->normals.write(first * sizeof(glm::vec3), run.data(), run.size() * sizeof(glm::vec3));
      });
  std::vector<std::pair<uint32_t, const FacePatch*>> faces;
  faces.reserve(p.faces.size());
  for (const FacePatch& f : p.faces) faces.emplace_back(f.face, &f);
  using Face = std::pair<uint32_t, const FacePatch*>;
  glBindVertexArray(face_vao_.get());
  for_each_run<Face, const FacePatch*>(
      faces, [](const Face& x) { return x.second; },
      [&](uint32_t first, const std::vector<const FacePatch*>& run) {
        std::vector<std::array<uint32_t, 3>> triangles;
        std::vector<glm::vec4> normals;
        for (const FacePatch* f : run) {
          triangles.push_back(f->triangle);
          normals.push_back(f->normal);
        }
        write_buffer(GL_ELEMENT_ARRAY_BUFFER, triangles_.get(), size_t(first) * 3 * sizeof(uint32_t), triangles.data(),
                     triangles.size() * 3 * sizeof(uint32_t));
        if (pull_) {
          pull_->corners.write(size_t(first) * 3 * sizeof(uint32_t), triangles.data(),
                               triangles.size() * 3 * sizeof(uint32_t));
        }
        face_normals.write(size_t(first) * sizeof(glm::vec4), normals.data(), normals.size() * sizeof(glm::vec4));
      });
  using Extra = std::pair<uint32_t, std::array<uint32_t, 3>>;
  glBindVertexArray(extra_vao_.get());
  for_each_run<Extra, std::array<uint32_t, 3>>(
      p.extra_triangles, [](const Extra& x) { return x.second; },
      [&](uint32_t first, const std::vector<std::array<uint32_t, 3>>& run) {
        write_buffer(GL_ELEMENT_ARRAY_BUFFER, extra_triangles_.get(), size_t(first) * 3 * sizeof(uint32_t), run.data(),
                     run.size() * 3 * sizeof(uint32_t));
        if (pull_) {
          pull_->extra_corners.write(size_t(first) * 3 * sizeof(uint32_t), run.data(),
                                     run.size() * 3 * sizeof(uint32_t));
        }
      });
  glBindVertexArray(0);
  using Edge = std::pair<uint32_t, EdgeSegment>;
  for_each_run<Edge, EdgeSegment>(
      p.edges, [](const Edge& x) { return x.second; },
      [&](uint32_t first, const std::vector<EdgeSegment>& run) { edges.write(first, run.data(), run.size()); });
  if (p.boundary_changed) {
    // The boundary batch is compact (drawn without the wireframe): the patch carries it whole.
    boundary_edges.upload(p.boundary_segments.data(), p.boundary_segments.size(), GL_DYNAMIC_DRAW);
  }
  points.set_count(p.vertex_capacity);
  edges.set_count(p.edge_capacity);
  face_count_ = p.face_capacity;
}

void GpuMesh::upload_arrows(const std::vector<EdgeSegment>& slot_arrows) {
  arrows.allocate(slot_arrows.data(), slot_arrows.size(), with_headroom(slot_arrows.size()));
}

void GpuMesh::apply_arrows(const SlotPatch& p) {
  using Arrow = std::pair<uint32_t, std::array<EdgeSegment, 3>>;
  for_each_run<Arrow, std::array<EdgeSegment, 3>>(
      p.arrows, [](const Arrow& x) { return x.second; },
      [&](uint32_t first, const std::vector<std::array<EdgeSegment, 3>>& run) {
        arrows.write(size_t(first) * 3, run.front().data(), run.size() * 3);
      });
  arrows.set_count(size_t(p.halfedge_capacity) * 3);
}

void GpuMesh::draw_triangles(GLint extra_location, GLuint unit) const {
  if (pull_) {
    draw_pulled_triangles(extra_location, unit);
    return;
  }
  glUniform1i(extra_location, 0);
  glBindVertexArray(face_vao_.get());
  glDrawElements(GL_TRIANGLES, GLsizei(face_count_ * 3), GL_UNSIGNED_INT, nullptr);
  if (extra_count_ == 0) return;
  extra_faces_.bind(unit);
  glUniform1i(extra_location, 1);
  glBindVertexArray(extra_vao_.get());
  glDrawElements(GL_TRIANGLES, GLsizei(extra_count_ * 3), GL_UNSIGNED_INT, nullptr);
}

namespace {
// `Array` is a std::vector or a MeshArray of T.
template <class Array>
void read_buffer(GLenum target, GLuint buffer, size_t count, Array& out) {
  using T = typename Array::value_type;
  out.resize(count);
  if (count == 0) return;
  glBindBuffer(target, buffer);
  glGetBufferSubData(target, 0, GLsizeiptr(count * sizeof(T)), out.data());
}
}  // namespace

void GpuMesh::read(SlotGeometry& out, std::vector<EdgeSegment>* slot_arrows) const {
  const size_t vertices = points.count();
  read_buffer(GL_ARRAY_BUFFER, positions_.get(), vertices, out.positions);
  read_buffer(GL_ARRAY_BUFFER, normals_.get(), vertices, out.smooth_normals);
  read_buffer(GL_ARRAY_BUFFER, points.buffer(), vertices, out.points);
  glBindVertexArray(face_vao_.get());
  read_buffer(GL_ELEMENT_ARRAY_BUFFER, triangles_.get(), face_count_ * 3, out.triangles);
  glBindVertexArray(extra_vao_.get());
  read_buffer(GL_ELEMENT_ARRAY_BUFFER, extra_triangles_.get(), extra_count_ * 3, out.extra_triangles);
  glBindVertexArray(0);
  read_buffer(kBufferTextureBinding, extra_faces_.buffer(), extra_count_, out.extra_faces);
  read_buffer(kBufferTextureBinding, face_normals.buffer(), face_count_, out.face_normals);
  read_buffer(kBufferTextureBinding, edges.buffer(), edges.count(), out.edges);
  std::vector<EdgeSegment> boundary;
  read_buffer(kBufferTextureBinding, boundary_edges.buffer(), boundary_edges.count(), boundary);
  out.boundary_edges.clear();
  for (const EdgeSegment& s : boundary) out.boundary_edges.push_back(s.edge);
  if (slot_arrows != nullptr) read_buffer(kBufferTextureBinding, arrows.buffer(), arrows.count(), *slot_arrows);
  glBindBuffer(kBufferTextureBinding, 0);
}

size_t GpuMesh::bytes() const {
  return vertex_slots_ * 2 * sizeof(glm::vec3) + face_slots_ * 3 * sizeof(uint32_t) +
         extra_count_ * 4 * sizeof(uint32_t) + face_normals.bytes() + edges.bytes() + boundary_edges.bytes() +
         arrows.bytes() + points.bytes() +
         (pull_ ? pull_->corners.bytes() + pull_->extra_corners.bytes() + pull_->positions.bytes() +
                      pull_->normals.bytes()
                : 0);
}

void GpuMesh::draw_pulled_triangles(GLint extra_location, GLuint unit) const {
  pull_->positions.bind(kPullUnits[1]);
  pull_->normals.bind(kPullUnits[2]);
  glBindVertexArray(pull_->no_attributes.get());
  glUniform1i(extra_location, 0);
  pull_->corners.bind(kPullUnits[0]);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(face_count_ * 3));
  if (extra_count_ == 0) return;
  extra_faces_.bind(unit);
  glUniform1i(extra_location, 1);
  pull_->extra_corners.bind(kPullUnits[0]);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(extra_count_ * 3));
}

}  // namespace meshedit::gl
