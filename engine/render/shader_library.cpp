// Finding, reading, compiling and linking the GLSL files of shaders/ (see shader_library.h).
#include "render/shader_library.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

#include "core/data_folders.h"
#include "core/file_bytes.h"
#include "render/gl_api.h"
#include "render/render_error.h"

namespace meshedit {
namespace {

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
  log.resize(std::char_traits<char>::length(log.c_str()));
  return log;
}

std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
  log.resize(std::char_traits<char>::length(log.c_str()));
  return log;
}

GLuint compile(GLenum type, const std::string& source, const std::filesystem::path& path) {
  const GLuint shader = glCreateShader(type);
  // The files have no #version line: the dialect's prologue (gl_api.h) comes first, then the file from its line 1.
  const char* texts[2] = {gl::kGlslPrologue, source.c_str()};
  glShaderSource(shader, 2, texts, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = shader_log(shader);
    glDeleteShader(shader);
    throw RenderError("shader " + path.string() + " does not compile:\n" + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::~ShaderProgram() {
  if (id_ != 0) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : id_(std::exchange(other.id_, 0)), name_(std::move(other.name_)), locations_(std::move(other.locations_)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
    name_ = std::move(other.name_);
    locations_ = std::move(other.locations_);
  }
  return *this;
}

void ShaderProgram::use() const { glUseProgram(id_); }

int ShaderProgram::uniform(const std::string& uniform_name) const {
  const auto found = locations_.find(uniform_name);
  if (found != locations_.end()) return found->second;
  const int location = glGetUniformLocation(id_, uniform_name.c_str());
  locations_.emplace(uniform_name, location);
  return location;
}

ShaderLibrary::ShaderLibrary() : dirs_(default_search_dirs()) {}

ShaderLibrary::ShaderLibrary(std::vector<std::filesystem::path> search_dirs) : dirs_(std::move(search_dirs)) {}

std::vector<std::filesystem::path> ShaderLibrary::default_search_dirs() {
  std::vector<std::filesystem::path> dirs;
  if (const char* env = std::getenv("MESHEDIT_SHADERS"); env != nullptr && *env != '\0') dirs.emplace_back(env);
  for (std::filesystem::path& dir : data_folder_candidates("shaders")) dirs.push_back(std::move(dir));
  return dirs;
}

std::filesystem::path ShaderLibrary::find(std::string_view name) const {
  std::string tried;
  for (const auto& dir : dirs_) {
    const auto path = dir / std::string(name);
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return path;
    tried += "\n  " + path.string();
  }
  if (dirs_.empty()) tried = " (no directories to search)";
  throw RenderError("shader " + std::string(name) + " not found; tried:" + tried +
                    "\n(set MESHEDIT_SHADERS to the project's shaders/ directory)");
}

std::string ShaderLibrary::read(std::string_view name) const {
  const auto path = find(name);
  FileBytes file = read_file_bytes(path);
  if (!file.ok()) throw RenderError("cannot read shader " + path.string());
  return std::move(file.bytes);
}

ShaderProgram ShaderLibrary::program(std::string_view vertex_file, std::string_view fragment_file) const {
  const auto vertex_path = find(vertex_file);
  const auto fragment_path = find(fragment_file);
  const GLuint vertex = compile(GL_VERTEX_SHADER, read(vertex_file), vertex_path);
  GLuint fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, read(fragment_file), fragment_path);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  const std::string name = std::string(vertex_file) + " + " + std::string(fragment_file);
  if (ok != GL_TRUE) {
    const std::string log = program_log(program);
    glDeleteProgram(program);
    throw RenderError("shaders " + vertex_path.string() + " and " + fragment_path.string() + " do not link:\n" + log);
  }
  return ShaderProgram(program, name);
}

}  // namespace meshedit
