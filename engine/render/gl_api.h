// The OpenGL API the renderer and the window draw with, in one header: OpenGL 3.3 core through libepoxy natively,
// OpenGL ES 3.0 (WebGL 2) through emscripten's GLES3 headers in the web build (MESHEDIT_GL_ES3, set by
// engine/render/CMakeLists.txt). Every file that calls GL includes this header first and no other GL header.
//
// Invariants: the two dialects differ only here and in what the names below say.
// - kGlslVersionLine: the #version line of the running GL's shading language (for ImGui's backend).
// - kGlslPrologue: what the shader loader (shader_library.cpp) puts before every file of shaders/, whose files have no
//   #version line of their own: the version, float and integer precision, and buffer_fetch(s, i), the i-th texel of
//   a buffer texture (samplerBuffer, usamplerBuffer). GLSL ES has no buffer textures, so there they are 2D textures
//   kBufferTextureWidth texels wide, filled row by row (gpu_batches.cpp's BufferTexture keeps that layout).
// - kBufferTextureBinding: the binding point a BufferTexture's buffer is written and read through.
// - enable_program_point_size, multisample_on, set_multisample, kCanSwitchMultisample, max_buffer_texture_texels:
//   the few calls whose GL 3.3 enums GLES lacks (point size from the shader and multisampling are always on there).
// - kHasPrimitiveId, and MESHEDIT_HAS_PRIMITIVE_ID in the prologue: 1 where fragment shaders have gl_PrimitiveID
//   (GLSL 330). GLSL ES 3.00 has none: there the face triangles are drawn without vertex arrays and pulled from
//   textures by gl_VertexID, which gives the triangle's number (gpu_mesh.h, shaders/face.vert).
#pragma once

#include <cstddef>

#if defined(MESHEDIT_GL_ES3)
#include <GLES3/gl3.h>
#include <webgl/webgl2.h>  // glGetBufferSubData, which WebGL 2 has and OpenGL ES 3.0 does not
#else
#include <epoxy/gl.h>
#endif

namespace meshedit::gl {

#if defined(MESHEDIT_GL_ES3)
inline constexpr bool kGlEs = true;
inline constexpr bool kHasPrimitiveId = false;
inline constexpr const char* kGlslVersionLine = "#version 300 es";
inline constexpr int kBufferTextureWidth = 2048;  // WebGL 2 guarantees 2048 texels per side at least
inline constexpr const char* kGlslPrologue =
    "#version 300 es\n"
    "precision highp float;\n"
    "precision highp int;\n"
    "precision highp sampler2D;\n"
    "precision highp usampler2D;\n"
    "#define samplerBuffer sampler2D\n"
    "#define usamplerBuffer usampler2D\n"
    "#define buffer_fetch(s, i) texelFetch(s, ivec2(int(i) % 2048, int(i) / 2048), 0)\n"
    "#define MESHEDIT_HAS_PRIMITIVE_ID 0\n"
    "#line 1\n";
inline constexpr GLenum kBufferTextureBinding = GL_PIXEL_UNPACK_BUFFER;  // the 2D texture is filled from it
inline constexpr bool kCanSwitchMultisample = false;
inline void enable_program_point_size() {}
inline bool multisample_on() {
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  return samples > 1;
}
inline void set_multisample(bool) {}
inline size_t max_buffer_texture_texels() {
  GLint side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &side);
  return size_t(kBufferTextureWidth) * size_t(side > 0 ? side : 0);
}
#else
inline constexpr bool kGlEs = false;
inline constexpr bool kHasPrimitiveId = true;
inline constexpr const char* kGlslVersionLine = "#version 330 core";
inline constexpr int kBufferTextureWidth = 0;  // buffer textures are one-dimensional
inline constexpr const char* kGlslPrologue =
    "#version 330 core\n"
    "#define buffer_fetch(s, i) texelFetch(s, i)\n"
    "#define MESHEDIT_HAS_PRIMITIVE_ID 1\n"
    "#line 1\n";
inline constexpr GLenum kBufferTextureBinding = GL_TEXTURE_BUFFER;
inline constexpr bool kCanSwitchMultisample = true;
inline void enable_program_point_size() { glEnable(GL_PROGRAM_POINT_SIZE); }
inline bool multisample_on() { return glIsEnabled(GL_MULTISAMPLE) == GL_TRUE; }
inline void set_multisample(bool on) { on ? glEnable(GL_MULTISAMPLE) : glDisable(GL_MULTISAMPLE); }
inline size_t max_buffer_texture_texels() {
  GLint texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
  return size_t(texels > 0 ? texels : 0);
}
#endif

}  // namespace meshedit::gl
