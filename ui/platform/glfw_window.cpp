// SPDX-License-Identifier: MIT
#include "ui/platform/glfw_window.h"

#define GLFW_INCLUDE_NONE
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace lamina::ui {

namespace {

std::string* g_glfw_error = nullptr;  // GLFW reports errors through a C callback

void OnGlfwError(int code, const char* description) {
  if (g_glfw_error) *g_glfw_error = "GLFW error " + std::to_string(code) + ": " + description;
}

}  // namespace

GlfwWindow::~GlfwWindow() {
  if (imgui_ready_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlfwWindow::Open(const std::string& title, int width, int height, std::string* error) {
  g_glfw_error = error;
  glfwSetErrorCallback(OnGlfwError);
  if (!glfwInit()) return false;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) return false;
  glfwMakeContextCurrent(window_);
  glfwSetWindowUserPointer(window_, this);
  glfwSetDropCallback(window_, &GlfwWindow::OnDrop);
  glfwSwapInterval(1);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  imgui_ready_ = true;
  g_glfw_error = nullptr;
  return true;
}

bool GlfwWindow::ShouldClose() const {
  return glfwWindowShouldClose(window_) != 0;
}

void GlfwWindow::SetShouldClose(bool close) {
  glfwSetWindowShouldClose(window_, close ? GLFW_TRUE : GLFW_FALSE);
}

void GlfwWindow::BeginFrame() {
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void GlfwWindow::EndFrame(float red, float green, float blue) {
  ImGui::Render();
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  glViewport(0, 0, width, height);
  glClearColor(red, green, blue, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void GlfwWindow::DrawImGui() {
  ImGui::Render();
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  glViewport(0, 0, width, height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void GlfwWindow::SetVsync(bool on) {
  glfwSwapInterval(on ? 1 : 0);
}

void GlfwWindow::SetTitle(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

void GlfwWindow::FramebufferSize(int* width, int* height) const {
  glfwGetFramebufferSize(window_, width, height);
}

std::vector<std::string> GlfwWindow::TakeDroppedPaths() {
  std::vector<std::string> paths;
  paths.swap(dropped_paths_);
  return paths;
}

void GlfwWindow::OnDrop(GLFWwindow* window, int count, const char** paths) {
  auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
  if (!self) return;
  for (int i = 0; i < count; ++i) self->dropped_paths_.emplace_back(paths[i]);
}

void GlfwWindow::Swap() {
  glfwSwapBuffers(window_);
}

std::vector<std::uint8_t> GlfwWindow::ReadPixels(int* width, int* height) const {
  glfwGetFramebufferSize(window_, width, height);
  std::vector<std::uint8_t> pixels(static_cast<size_t>(*width) * *height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, *width, *height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  return pixels;
}

std::string GlfwWindow::GlVersion() const {
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return version ? version : "";
}

}  // namespace lamina::ui
