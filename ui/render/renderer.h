// SPDX-License-Identifier: MIT
// The renderer: draws a core::RenderScene with an OrbitCamera into whatever OpenGL 3.3 core
// context is current (a GLFW window or an OSMesa buffer) — sky gradient, lit meshes with a
// shadowed sun, checkered terrain, translucent layers, then the debug overlays (also faintly
// where they are hidden). It never creates a context.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/render/camera.h"
#include "core/render/render_scene.h"
#include "core/sensors/sensor.h"

namespace lamina::ui {

struct RenderSettings {
  bool shadows = true;
  int shadow_map_size = 2048;  ///< texels per side
  int samples = 4;             ///< multisampling per pixel, clamped to what the context allows
  /// One sample per pixel smoothed by an FXAA pass instead of multisampling (`samples` is then
  /// ignored): about as cheap as no antialiasing on a software renderer.
  bool fxaa = false;
  double checker_size = 0.0;  ///< terrain checker square (m); 0 = chosen from the scene size
};

/// Mesa's software rasterizers (llvmpipe, softpipe, swrast), where multisampling costs more than
/// the rest of a frame.
bool IsSoftwareRenderer(const std::string& gl_renderer);
/// The shadow map on a software rasterizer: a quarter of the 2048² texels (2–3 ms a frame less
/// for the ATHLETE world at 1280x720 on llvmpipe; docs/rendering.md).
inline constexpr int kSoftwareShadowMapSize = 1024;

class Renderer {
 public:
  Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  /// Frees the GL objects: the context it was initialized in must be current.
  ~Renderer();

  /// Checks that the current context is OpenGL >= 3.3 and builds shaders and buffers. False with
  /// a message (GL version found, or the shader log) otherwise.
  bool Initialize(std::string* error);

  /// Draws `scene` seen by `camera` into `framebuffer` (0 = the context's default one), which is
  /// `width` x `height` pixels.
  void Render(const core::RenderScene& scene, const core::OrbitCamera& camera, int width,
              int height, unsigned framebuffer = 0);

  /// Draws `scene` (without overlays) as a sensor camera sees it (request.camera: z forward,
  /// x right, y down; horizontal field of view request.xfov, the vertical one from the aspect;
  /// clip planes znear, zfar) into an off-screen target of one sample per pixel and reads back
  /// its colour and its depth along the optical axis (m, +inf where nothing was drawn), top row
  /// first. False without Initialize or with an empty size.
  bool RenderCamera(const core::RenderScene& scene, const core::CameraRequest& request,
                    core::CameraImage* image);

  /// The pixels of `framebuffer` as RGBA8, bottom row first (as OpenGL reads them).
  std::vector<std::uint8_t> ReadPixels(int width, int height, unsigned framebuffer = 0) const;

  RenderSettings& settings() { return settings_; }
  const RenderSettings& settings() const { return settings_; }
  /// GL_VERSION and GL_RENDERER of the context (after Initialize).
  const std::string& gl_version() const { return gl_version_; }
  const std::string& gl_renderer() const { return gl_renderer_; }
  /// Samples per pixel of the last frame (1 without multisampling, and with FXAA).
  int samples_used() const { return samples_used_; }

 private:
  struct Resources;
  struct FrameParameters;

  FrameParameters PrepareFrame(const core::RenderScene& scene, const core::OrbitCamera& camera,
                               int width, int height) const;
  FrameParameters PrepareCameraFrame(const core::RenderScene& scene,
                                     const core::CameraRequest& request) const;
  void SetSun(const Eigen::Vector3f& focus, float across, float along,
              FrameParameters* frame) const;
  void ReadCameraImage(const core::CameraRequest& request, core::CameraImage* image) const;
  void DrawShadowPass(const core::RenderScene& scene, const FrameParameters& frame);
  void DrawBackground(const FrameParameters& frame);
  void BindMeshProgram(const FrameParameters& frame);
  void DrawItem(const Eigen::Matrix4f& transform, const core::Rgba& color, std::uint32_t flags,
                const core::RenderMesh& mesh);
  void DrawOpaqueItems(const core::RenderScene& scene);
  void DrawTranslucentItems(const core::RenderScene& scene, const FrameParameters& frame);
  void DrawOverlays(const core::RenderScene& scene, const FrameParameters& frame,
                    float alpha_scale);
  void DrawLines(const core::RenderScene& scene, const FrameParameters& frame, float alpha_scale);
  void DrawFxaa(unsigned framebuffer, int width, int height);
  /// Whether the context's own framebuffer has a depth buffer (asked once).
  bool DefaultFramebufferHasDepth();

  RenderSettings settings_;
  std::unique_ptr<Resources> resources_;
  std::string gl_version_, gl_renderer_;
  int max_samples_ = 1;
  int samples_used_ = 1;
  int default_depth_bits_ = -1;  ///< -1: not asked yet
};

}  // namespace lamina::ui
