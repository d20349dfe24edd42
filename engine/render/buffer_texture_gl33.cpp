// BufferTexture on OpenGL 3.3 core (see gpu_batches.h): a buffer texture (GL_TEXTURE_BUFFER) over its own buffer, the
// shaders' samplerBuffer / usamplerBuffer read with texelFetch. The web build has buffer_texture_es3.cpp instead
// (engine/render/CMakeLists.txt picks one).
#include <algorithm>

#include "render/gpu_batches.h"

namespace meshedit::gl {

BufferTexture::BufferTexture(GLenum format) : format_(format), buffer_(make_buffer()), texture_(make_texture()) {}

void BufferTexture::upload(const void* data, size_t bytes, GLenum usage) {
  static const uint32_t kZero[4] = {0, 0, 0, 0};
  glBindBuffer(GL_TEXTURE_BUFFER, buffer_.get());
  if (bytes == 0) {
    glBufferData(GL_TEXTURE_BUFFER, sizeof kZero, kZero, usage);
  } else {
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(bytes), data, usage);
  }
  glBindTexture(GL_TEXTURE_BUFFER, texture_.get());
  glTexBuffer(GL_TEXTURE_BUFFER, format_, buffer_.get());
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
  count_upload(bytes);
  bytes_ = bytes;
}

void BufferTexture::allocate(size_t capacity, const void* data, size_t bytes) {
  allocate_buffer(GL_TEXTURE_BUFFER, buffer_.get(), capacity, data, bytes);
  glBindTexture(GL_TEXTURE_BUFFER, texture_.get());
  glTexBuffer(GL_TEXTURE_BUFFER, format_, buffer_.get());
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
  bytes_ = std::max<size_t>(capacity, 16);
}

void BufferTexture::write(size_t offset, const void* data, size_t bytes) {
  write_buffer(GL_TEXTURE_BUFFER, buffer_.get(), offset, data, bytes);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void BufferTexture::bind(GLuint unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_BUFFER, texture_.get());
}

}  // namespace meshedit::gl
