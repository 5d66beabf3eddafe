// SPDX-License-Identifier: MIT
// The editor's window: GLFW with an OpenGL 3.3 core context and a Dear ImGui frame around
// whatever the caller draws; files dropped onto it are queued for the caller.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace lamina::ui {

class GlfwWindow {
 public:
  GlfwWindow() = default;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;
  ~GlfwWindow();

  /// Opens the window; false (with `error` set) when GLFW or the GL context fails.
  bool Open(const std::string& title, int width, int height, std::string* error);
  bool ShouldClose() const;
  /// Sets or clears the close request (the editor clears it to ask about unsaved edits first).
  void SetShouldClose(bool close);
  /// Polls events and starts an ImGui frame.
  void BeginFrame();
  /// Clears the framebuffer to `rgb` and draws the ImGui frame; does not swap.
  void EndFrame(float red, float green, float blue);
  /// Draws the ImGui frame over what is in the framebuffer (no clear); does not swap.
  void DrawImGui();
  void Swap();
  /// Waits for vertical sync on Swap (on by default; off for benchmarks).
  void SetVsync(bool on);
  void SetTitle(const std::string& title);
  /// Framebuffer size in pixels.
  void FramebufferSize(int* width, int* height) const;
  /// Files dropped onto the window since the last call, in drop order.
  std::vector<std::string> TakeDroppedPaths();
  /// The back buffer as RGBA8, bottom row first.
  std::vector<std::uint8_t> ReadPixels(int* width, int* height) const;
  /// "4.5 (Core Profile) Mesa ..." of the current context.
  std::string GlVersion() const;

 private:
  GLFWwindow* window_ = nullptr;
  bool imgui_ready_ = false;
  std::vector<std::string> dropped_paths_;

  static void OnDrop(GLFWwindow* window, int count, const char** paths);
};

}  // namespace lamina::ui
