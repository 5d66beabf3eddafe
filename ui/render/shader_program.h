// SPDX-License-Identifier: MIT
// A linked GLSL program built from two embedded shaders, with cached uniform locations.
#pragma once

#include <map>
#include <string>

#include <Eigen/Core>

namespace lamina::ui {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  ~ShaderProgram();

  /// Compiles and links shaders/<vertex> and shaders/<fragment>; false with the compiler's log
  /// in `error` on failure. Needs a current GL context.
  bool Build(const char* vertex, const char* fragment, std::string* error);
  void Use() const;
  unsigned id() const { return program_; }

  void Set(const char* name, int value);
  void Set(const char* name, float value);
  void Set(const char* name, const Eigen::Vector2f& value);
  void Set(const char* name, const Eigen::Vector3f& value);
  void Set(const char* name, const Eigen::Vector4f& value);
  void Set(const char* name, const Eigen::Matrix3f& value);
  void Set(const char* name, const Eigen::Matrix4f& value);

 private:
  int Location(const char* name);

  unsigned program_ = 0;
  std::map<std::string, int> locations_;
};

}  // namespace lamina::ui
