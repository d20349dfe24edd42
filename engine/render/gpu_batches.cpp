// Vertex arrays for segments and points, and buffer textures (see gpu_batches.h).
#include "render/gpu_batches.h"

#include <algorithm>
#include <cstddef>

#include <glm/gtc/type_ptr.hpp>

namespace meshedit::gl {
namespace {

static_assert(sizeof(EdgeSegment) == 32, "EdgeSegment is uploaded as is");
static_assert(sizeof(VertexPoint) == 16, "VertexPoint is uploaded as is");
static_assert(sizeof(ItemStyle) == 8, "ItemStyle is uploaded as is");

// GL takes a buffer offset as a pointer.
const void* offset(size_t bytes) { return reinterpret_cast<const void*>(bytes); }  // NOLINT(performance-no-int-to-ptr)

void style_attributes(GLuint colour, GLuint size) {
  glEnableVertexAttribArray(colour);
  glVertexAttribPointer(colour, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ItemStyle), offset(offsetof(ItemStyle, rgba)));
  glEnableVertexAttribArray(size);
  glVertexAttribPointer(size, 1, GL_FLOAT, GL_FALSE, sizeof(ItemStyle), offset(offsetof(ItemStyle, size)));
}

size_t g_uploaded_bytes = 0;

}  // namespace

size_t uploaded_bytes() { return g_uploaded_bytes; }
void count_upload(size_t bytes) { g_uploaded_bytes += bytes; }

void write_buffer(GLenum target, GLuint buffer, size_t offset, const void* data, size_t bytes) {
  if (bytes == 0) return;
  glBindBuffer(target, buffer);
  glBufferSubData(target, GLintptr(offset), GLsizeiptr(bytes), data);
  count_upload(bytes);
}

void allocate_buffer(GLenum target, GLuint buffer, size_t capacity, const void* data, size_t bytes) {
  glBindBuffer(target, buffer);
  const GLsizeiptr size = GLsizeiptr(std::max<size_t>(capacity, 16));
  GLint64 current = 0;
  glGetBufferParameteri64v(target, GL_BUFFER_SIZE, &current);
  if (current != size) glBufferData(target, size, nullptr, GL_DYNAMIC_DRAW);
  if (bytes > 0) glBufferSubData(target, 0, GLsizeiptr(bytes), data);
  count_upload(bytes);
}

SegmentBatch::SegmentBatch() : vao_(make_vertex_array()), items_(GL_RGBA32UI), styles_(GL_RG32UI) {}

void SegmentBatch::upload(const EdgeSegment* items, size_t count, GLenum usage) {
  items_.upload(items, count * sizeof(EdgeSegment), usage);
  count_ = capacity_ = count;
}

void SegmentBatch::allocate(const EdgeSegment* items, size_t count, size_t capacity) {
  items_.allocate(capacity * sizeof(EdgeSegment), items, count * sizeof(EdgeSegment));
  count_ = count;
  capacity_ = capacity;
}

void SegmentBatch::write(size_t first, const EdgeSegment* items, size_t count) {
  items_.write(first * sizeof(EdgeSegment), items, count * sizeof(EdgeSegment));
}

void SegmentBatch::upload_styles(const ItemStyle* styles, size_t count, GLenum usage) {
  styles_.upload(styles, count * sizeof(ItemStyle), usage);
}

size_t SegmentBatch::bytes() const { return items_.bytes() + styles_.bytes(); }

void SegmentBatch::draw() const {
  if (count_ == 0) return;
  items_.bind(1);
  styles_.bind(2);
  glBindVertexArray(vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(count_ * 6));
}

void SegmentBatch::draw_lines() const {
  if (count_ == 0) return;
  items_.bind(1);
  styles_.bind(2);
  glBindVertexArray(vao_.get());
  glDrawArrays(GL_LINES, 0, GLsizei(count_ * 2));
}

PointBatch::PointBatch() : vao_(make_vertex_array()), items_(make_buffer()), styles_(make_buffer()) {
  glBindVertexArray(vao_.get());
  glBindBuffer(GL_ARRAY_BUFFER, items_.get());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(VertexPoint), offset(offsetof(VertexPoint, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, sizeof(VertexPoint), offset(offsetof(VertexPoint, vertex)));
  glBindVertexArray(0);
}

void PointBatch::upload(const VertexPoint* items, size_t count, GLenum usage) {
  glBindBuffer(GL_ARRAY_BUFFER, items_.get());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(count * sizeof(VertexPoint)), items, usage);
  count_upload(count * sizeof(VertexPoint));
  count_ = count;
  bytes_ = count * sizeof(VertexPoint);
}

void PointBatch::allocate(const VertexPoint* items, size_t count, size_t capacity) {
  allocate_buffer(GL_ARRAY_BUFFER, items_.get(), capacity * sizeof(VertexPoint), items, count * sizeof(VertexPoint));
  count_ = count;
  bytes_ = std::max<size_t>(capacity * sizeof(VertexPoint), 16);
}

void PointBatch::write(size_t first, const VertexPoint* items, size_t count) {
  write_buffer(GL_ARRAY_BUFFER, items_.get(), first * sizeof(VertexPoint), items, count * sizeof(VertexPoint));
}

void PointBatch::upload_styles(const ItemStyle* styles, size_t count, GLenum usage) {
  glBindVertexArray(vao_.get());
  glBindBuffer(GL_ARRAY_BUFFER, styles_.get());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(count * sizeof(ItemStyle)), styles, usage);
  style_attributes(2, 3);
  glBindVertexArray(0);
}

void PointBatch::draw() const {
  if (count_ == 0) return;
  glBindVertexArray(vao_.get());
  glDrawArrays(GL_POINTS, 0, GLsizei(count_));
}

CameraUniforms camera_uniforms(const OrbitCamera& camera, Viewport viewport) {
  CameraUniforms out;
  const glm::dmat4 projection = camera.projection(viewport.aspect());
  out.view = glm::mat4(camera.view());
  out.projection = glm::mat4(projection);
  out.view_projection = glm::mat4(projection * camera.view());
  out.viewport[0] = float(viewport.width);
  out.viewport[1] = float(viewport.height);
  out.pixel_scale = float(2.0 / (projection[1][1] * double(std::max(viewport.height, 1))));
  return out;
}

void set_camera(const ShaderProgram& program, const CameraUniforms& camera) {
  glUniformMatrix4fv(program.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(camera.view_projection));
  glUniformMatrix4fv(program.uniform("u_view"), 1, GL_FALSE, glm::value_ptr(camera.view));
  glUniformMatrix4fv(program.uniform("u_projection"), 1, GL_FALSE, glm::value_ptr(camera.projection));
  glUniform2fv(program.uniform("u_viewport"), 1, camera.viewport);
  glUniform1f(program.uniform("u_pixel_scale"), camera.pixel_scale);
}

}  // namespace meshedit::gl
