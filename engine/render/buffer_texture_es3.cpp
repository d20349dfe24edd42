// BufferTexture on OpenGL ES 3.0 / WebGL 2 (see gpu_batches.h), which has no buffer textures: the buffer is kept as
// on the desktop (written, and read back, through GL_PIXEL_UNPACK_BUFFER) and a 2D texture kBufferTextureWidth texels
// wide holds the same texels row by row, copied from the buffer on the GPU after every write. The shaders read texel
// i at (i % width, i / width) through buffer_fetch (render/gl_api.h). The desktop build has buffer_texture_gl33.cpp.
//
// Invariants: after upload, allocate or write returns, every texel the buffer's written bytes cover is in the
// texture; the texture has at least one row, so a fetch is always defined; integer and float textures alike sample
// with NEAREST and no mipmaps (texelFetch needs a complete texture).
#include <algorithm>

#include "render/gpu_batches.h"
#include "render/render_error.h"

namespace meshedit::gl {
namespace {

struct TexelFormat {
  GLenum format;
  GLenum type;
  size_t bytes;
};

TexelFormat texel_format(GLenum internal_format) {
  switch (internal_format) {
    case GL_R8UI: return {GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1};
    case GL_R32UI: return {GL_RED_INTEGER, GL_UNSIGNED_INT, 4};
    case GL_RG32UI: return {GL_RG_INTEGER, GL_UNSIGNED_INT, 8};
    case GL_RGB32UI: return {GL_RGB_INTEGER, GL_UNSIGNED_INT, 12};
    case GL_RGBA32UI: return {GL_RGBA_INTEGER, GL_UNSIGNED_INT, 16};
    case GL_RGB32F: return {GL_RGB, GL_FLOAT, 12};
    case GL_RGBA32F: return {GL_RGBA, GL_FLOAT, 16};
    default: throw RenderError("a buffer texture of format " + std::to_string(internal_format) + " has no GLES layout");
  }
}

constexpr size_t kWidth = size_t(kBufferTextureWidth);

// Texture storage for `bytes` of texels (one row at least), its content undefined. Unbinds the unpack buffer (with
// one bound, glTexImage2D would read the storage's texels from it).
void define_texture(GLuint texture, GLenum internal_format, size_t bytes) {
  const TexelFormat f = texel_format(internal_format);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  const size_t texels = std::max<size_t>(1, (bytes + f.bytes - 1) / f.bytes);
  const size_t rows = (texels + kWidth - 1) / kWidth;
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal_format), GLsizei(kWidth), GLsizei(rows), 0, f.format, f.type, nullptr);
}

// Copies the whole texels within bytes [offset, offset + bytes) of `buffer` into the texture, through
// GL_PIXEL_UNPACK_BUFFER (left bound): the partial first row, the full rows, the partial last row.
void copy_texels(GLuint texture, GLuint buffer, GLenum internal_format, size_t offset, size_t bytes) {
  const TexelFormat f = texel_format(internal_format);
  size_t texel = offset / f.bytes;
  const size_t end = (offset + bytes) / f.bytes;
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer);
  if (texel >= end) return;
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const auto rect = [&](size_t x, size_t y, size_t w, size_t h) {
    glTexSubImage2D(GL_TEXTURE_2D, 0, GLint(x), GLint(y), GLsizei(w), GLsizei(h), f.format, f.type,
                    reinterpret_cast<const void*>(texel * f.bytes));
    texel += w * h;
  };
  if (texel % kWidth != 0) rect(texel % kWidth, texel / kWidth, std::min(kWidth - texel % kWidth, end - texel), 1);
  if (end - texel >= kWidth) rect(0, texel / kWidth, kWidth, (end - texel) / kWidth);
  if (texel < end) rect(0, texel / kWidth, end - texel, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

}  // namespace

BufferTexture::BufferTexture(GLenum format) : format_(format), buffer_(make_buffer()), texture_(make_texture()) {
  texel_format(format);  // refuses a format with no layout before anything is drawn
}

void BufferTexture::upload(const void* data, size_t bytes, GLenum usage) {
  static const uint32_t zero[4] = {0, 0, 0, 0};
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer_.get());
  if (bytes == 0) {
    glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof zero, zero, usage);
  } else {
    glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(bytes), data, usage);
  }
  const size_t stored = bytes == 0 ? sizeof zero : bytes;
  define_texture(texture_.get(), format_, stored);
  copy_texels(texture_.get(), buffer_.get(), format_, 0, stored);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  count_upload(bytes);
  bytes_ = bytes;
}

void BufferTexture::allocate(size_t capacity, const void* data, size_t bytes) {
  allocate_buffer(GL_PIXEL_UNPACK_BUFFER, buffer_.get(), capacity, data, bytes);
  bytes_ = std::max<size_t>(capacity, 16);
  define_texture(texture_.get(), format_, bytes_);
  copy_texels(texture_.get(), buffer_.get(), format_, 0, bytes);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

void BufferTexture::write(size_t offset, const void* data, size_t bytes) {
  write_buffer(GL_PIXEL_UNPACK_BUFFER, buffer_.get(), offset, data, bytes);
  copy_texels(texture_.get(), buffer_.get(), format_, offset, bytes);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

void BufferTexture::bind(GLuint unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture_.get());
}

}  // namespace meshedit::gl
