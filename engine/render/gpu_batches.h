// Internal to engine/render: the vertex arrays behind every line and point the renderers draw.
//
// SegmentBatch: segments (EdgeSegment layout: start, end, id, flags) in a buffer texture, drawn as two
// triangles each by shaders/segment.vert; optional per-segment styles (RGBA8 colour, width) for overlays.
// PointBatch: points (VertexPoint layout: position, id), optional per-point styles (colour, size).
// Invariant: count() is the number of items drawn: those of the last upload, or of allocate() and set_count().
// Styles are read only by overlays (u_element_colours false); mesh batches have none and take colours from their
// elements' state.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/mat4x4.hpp>

#include "render/camera.h"
#include "render/gl_api.h"
#include "render/gl_objects.h"
#include "render/mesh_geometry.h"
#include "render/shader_library.h"

namespace meshedit::gl {

struct ItemStyle {
  uint8_t rgba[4] = {255, 255, 255, 255};
  float size = 1.0f;  // width of a segment or diameter of a point, in pixels
};

// Bytes sent to the GPU by every upload and write below and by the renderer's own buffer writes, since the
// program started (the renderer reports the difference across one update).
size_t uploaded_bytes();
void count_upload(size_t bytes);
// glBufferSubData of `bytes` at `offset` into `buffer` (bound to `target`), counted.
void write_buffer(GLenum target, GLuint buffer, size_t offset, const void* data, size_t bytes);
// A buffer of `capacity` bytes, the first `bytes` from `data` (counted), the rest undefined. A buffer that already
// has exactly that size keeps its storage (only the data is written): a full rebuild at the same slot counts then
// faults in no fresh driver memory (on llvmpipe, fresh memory costs far more than the copy itself).
void allocate_buffer(GLenum target, GLuint buffer, size_t capacity, const void* data, size_t bytes);

// A buffer texture (samplerBuffer / usamplerBuffer) over its own buffer; `format` e.g. GL_R32UI.
class BufferTexture {
 public:
  explicit BufferTexture(GLenum format);
  // Never empty on the GPU (one zero element at least), so a fetch is always defined.
  void upload(const void* data, size_t bytes, GLenum usage);
  // Room for `capacity` bytes, the first `bytes` from `data`; later write()s fill the rest in place.
  void allocate(size_t capacity, const void* data, size_t bytes);
  void write(size_t offset, const void* data, size_t bytes);
  void bind(GLuint unit) const;
  size_t bytes() const { return bytes_; }  // allocated
  GLuint buffer() const { return buffer_.get(); }

 private:
  GLenum format_;
  Buffer buffer_;
  Texture texture_;
  size_t bytes_ = 0;
};

// Segments are pulled by the vertex shader from a buffer texture by gl_VertexID (instancing cost
// llvmpipe about a microsecond per segment): two triangles each, or one GL_LINES line.
class SegmentBatch {
 public:
  SegmentBatch();
  void upload(const EdgeSegment* items, size_t count, GLenum usage);
  // Room for `capacity` segments, the first `count` from `items`; write() rewrites segments in place and
  // set_count() says how many are drawn.
  void allocate(const EdgeSegment* items, size_t count, size_t capacity);
  void write(size_t first, const EdgeSegment* items, size_t count);
  void set_count(size_t count) { count_ = count; }
  size_t capacity() const { return capacity_; }
  void upload_styles(const ItemStyle* styles, size_t count, GLenum usage);
  // Binds the segments to texture unit 1 and the styles to unit 2 (the shaders' u_segments, u_styles)
  // and draws two triangles per segment.
  void draw() const;
  // The same as one-pixel GL_LINES (the shader's u_lines must be true): a third of the vertices and
  // half the primitives, for the full wireframe.
  void draw_lines() const;
  size_t count() const { return count_; }
  size_t bytes() const;
  GLuint buffer() const { return items_.buffer(); }

 private:
  VertexArray vao_;  // holds no attributes; core profile needs one bound to draw
  BufferTexture items_, styles_;
  size_t count_ = 0, capacity_ = 0;
};

class PointBatch {
 public:
  PointBatch();
  void upload(const VertexPoint* items, size_t count, GLenum usage);
  // As SegmentBatch's.
  void allocate(const VertexPoint* items, size_t count, size_t capacity);
  void write(size_t first, const VertexPoint* items, size_t count);
  void set_count(size_t count) { count_ = count; }
  size_t capacity() const { return bytes_ / sizeof(VertexPoint); }
  void upload_styles(const ItemStyle* styles, size_t count, GLenum usage);
  void draw() const;
  size_t count() const { return count_; }
  size_t bytes() const { return bytes_; }
  GLuint buffer() const { return items_.get(); }

 private:
  VertexArray vao_;
  Buffer items_, styles_;
  size_t count_ = 0, bytes_ = 0;
};

// The camera as the shaders take it, computed once per pass.
struct CameraUniforms {
  glm::mat4 view{1.0f}, projection{1.0f}, view_projection{1.0f};
  float viewport[2] = {1.0f, 1.0f};
  float pixel_scale = 0.0f;  // world size of a pixel at unit view depth
};
CameraUniforms camera_uniforms(const OrbitCamera& camera, Viewport viewport);
// Sets whichever of u_view_projection, u_view, u_projection, u_viewport, u_pixel_scale the program has.
void set_camera(const ShaderProgram& program, const CameraUniforms& camera);

}  // namespace meshedit::gl
