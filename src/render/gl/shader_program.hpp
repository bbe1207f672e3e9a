#pragma once
// Private: a linked GLSL program, deleted with its owner. Needs a current context throughout.
#include <string>

namespace collide::render {

class ShaderProgram {
 public:
  // Compiles and links; throws RenderError with the GL info log (first line) on failure.
  // `fragment_defines` (lines such as "#define X 1\n") go right after the fragment source's first
  // line, its #version.
  ShaderProgram(const char* vertex_source, const char* fragment_source, const std::string& name,
                const std::string& fragment_defines = "");
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  unsigned id() const { return program_; }
  // Location of a uniform that must exist; throws RenderError otherwise.
  int uniformLocation(const char* uniform_name) const;

 private:
  unsigned program_ = 0;
  std::string name_;
};

}  // namespace collide::render
