#include "render/gl/shader_program.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

#include "render/gl/gl.hpp"
#include "render/gl_context.hpp"

namespace collide::render {
namespace {

// GL info logs are multi-line; errors here must stay one line.
std::string oneLine(std::string log) {
  for (char& c : log) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!log.empty() && (log.back() == ' ' || log.back() == '\0')) log.pop_back();
  return log;
}

// The info log of a shader (glGetShaderiv, glGetShaderInfoLog) or a program (glGetProgramiv,
// glGetProgramInfoLog), on one line.
using GetParameter = void (*)(GLuint, GLenum, GLint*);
using GetInfoLog = void (*)(GLuint, GLsizei, GLsizei*, GLchar*);
std::string infoLog(GLuint object, GetParameter get_parameter, GetInfoLog get_info_log) {
  GLint length = 0;
  get_parameter(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  get_info_log(object, length, nullptr, log.data());
  return oneLine(log.data());
}

// `defines` go after the source's first line (#version must come first).
GLuint compile(GLenum stage, const char* source, const std::string& what,
               const std::string& defines = "") {
  const GLuint shader = glCreateShader(stage);
  const std::string_view text(source);
  const std::size_t first_line = std::min(text.size(), text.find('\n') + 1);
  const char* parts[3] = {source, defines.c_str(), source + first_line};
  const GLint lengths[3] = {static_cast<GLint>(first_line), static_cast<GLint>(defines.size()),
                            static_cast<GLint>(text.size() - first_line)};
  glShaderSource(shader, 3, parts, lengths);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = infoLog(shader, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(shader);
    throw RenderError("cannot compile " + what + ": " + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const char* vertex_source, const char* fragment_source,
                             const std::string& name, const std::string& fragment_defines)
    : name_(name) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source, name + " vertex shader");
  GLuint fragment = 0;
  try {
    fragment =
        compile(GL_FRAGMENT_SHADER, fragment_source, name + " fragment shader", fragment_defines);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  // The program keeps the compiled stages; the shader objects can go now.
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = infoLog(program_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(program_);
    throw RenderError("cannot link the " + name + " shader program: " + log);
  }
}

ShaderProgram::~ShaderProgram() {
  glDeleteProgram(program_);
}

int ShaderProgram::uniformLocation(const char* uniform_name) const {
  const GLint location = glGetUniformLocation(program_, uniform_name);
  if (location < 0) {
    throw RenderError("the " + name_ + " shader program has no uniform " + uniform_name);
  }
  return location;
}

}  // namespace collide::render
