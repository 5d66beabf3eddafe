// SPDX-License-Identifier: MIT
// Shader compilation, linking and uniform upload.
#include "ui/render/shader_program.h"

#include <vector>

#include "ui/render/embedded_shaders.h"
#include "ui/render/gl_api.h"

namespace lamina::ui {

namespace {

std::string ShaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(std::max(length, 1));
  glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.data();
}

GLuint Compile(GLenum type, const char* name, std::string* error) {
  const char* source = EmbeddedShader(name);
  if (source == nullptr) {
    *error = std::string("no embedded shader ") + name;
    return 0;
  }
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    *error = std::string("shaders/") + name + ": " + ShaderLog(shader);
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

ShaderProgram::~ShaderProgram() {
  if (program_ != 0) glDeleteProgram(program_);
}

bool ShaderProgram::Build(const char* vertex, const char* fragment, std::string* error) {
  const GLuint vs = Compile(GL_VERTEX_SHADER, vertex, error);
  if (vs == 0) return false;
  const GLuint fs = Compile(GL_FRAGMENT_SHADER, fragment, error);
  if (fs == 0) {
    glDeleteShader(vs);
    return false;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {0};
    glGetProgramInfoLog(program_, sizeof(log), nullptr, log);
    *error = std::string("linking ") + vertex + " + " + fragment + ": " + log;
    return false;
  }
  return true;
}

void ShaderProgram::Use() const {
  glUseProgram(program_);
}

int ShaderProgram::Location(const char* name) {
  const auto found = locations_.find(name);
  if (found != locations_.end()) return found->second;
  const int location = glGetUniformLocation(program_, name);
  locations_.emplace(name, location);
  return location;
}

void ShaderProgram::Set(const char* name, int value) {
  glUniform1i(Location(name), value);
}
void ShaderProgram::Set(const char* name, float value) {
  glUniform1f(Location(name), value);
}
void ShaderProgram::Set(const char* name, const Eigen::Vector2f& value) {
  glUniform2fv(Location(name), 1, value.data());
}
void ShaderProgram::Set(const char* name, const Eigen::Vector3f& value) {
  glUniform3fv(Location(name), 1, value.data());
}
void ShaderProgram::Set(const char* name, const Eigen::Vector4f& value) {
  glUniform4fv(Location(name), 1, value.data());
}
// Eigen matrices are column-major, as GL expects
void ShaderProgram::Set(const char* name, const Eigen::Matrix3f& value) {
  glUniformMatrix3fv(Location(name), 1, GL_FALSE, value.data());
}
void ShaderProgram::Set(const char* name, const Eigen::Matrix4f& value) {
  glUniformMatrix4fv(Location(name), 1, GL_FALSE, value.data());
}

}  // namespace lamina::ui
