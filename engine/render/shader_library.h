// ShaderLibrary: finds the GLSL files in shaders/ and builds programs from them. ShaderProgram: one
// linked program with its uniform locations.
//
// Where shaders are looked for, in order (the first directory holding the file wins, per file):
//   1. $MESHEDIT_SHADERS, when set;
//   2. data_folder_candidates("shaders") (core/data_folders.h): beside the running binary, in the installed layout
//      (<prefix>/share/meshedit/shaders), then in the source tree (compiled in: a build tree finds its sources).
// A missing file is a RenderError listing every path that was tried; a compile or link error is a
// RenderError quoting the file names and the driver's log. Shaders are GLSL 330 core or GLSL ES 3.00 (WebGL 2),
// written once without a #version line: the loader puts the running GL's prologue first (render/gl_api.h).
// Building programs needs a current OpenGL 3.3 core context; finding and reading files does not.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace meshedit {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  ShaderProgram(unsigned id, std::string name) : id_(id), name_(std::move(name)) {}
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  unsigned id() const { return id_; }
  const std::string& name() const { return name_; }  // "face.vert + face.frag"
  void use() const;
  // The uniform's location (cached), or -1 if the program has no active uniform of that name.
  int uniform(const std::string& uniform_name) const;

 private:
  unsigned id_ = 0;
  std::string name_;
  mutable std::unordered_map<std::string, int> locations_;
};

class ShaderLibrary {
 public:
  // The default search path described above.
  ShaderLibrary();
  explicit ShaderLibrary(std::vector<std::filesystem::path> search_dirs);

  static std::vector<std::filesystem::path> default_search_dirs();
  const std::vector<std::filesystem::path>& search_dirs() const { return dirs_; }

  // The first existing search_dir/name; RenderError naming every path tried if there is none.
  std::filesystem::path find(std::string_view name) const;
  std::string read(std::string_view name) const;
  // Compiles and links two files (e.g. "face.vert", "face.frag"); needs a current GL context.
  ShaderProgram program(std::string_view vertex_file, std::string_view fragment_file) const;

 private:
  std::vector<std::filesystem::path> dirs_;
};

}  // namespace meshedit
