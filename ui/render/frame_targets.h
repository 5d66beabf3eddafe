// SPDX-License-Identifier: MIT
// Off-screen framebuffers the renderer draws into: the (multisampled) colour + depth target that
// is resolved into the caller's framebuffer, the colour texture of the FXAA pass, and the sun's
// shadow map.
#pragma once

namespace lamina::ui {

/// A colour + depth framebuffer with `samples` samples per pixel (1 = no multisampling).
class SceneTarget {
 public:
  SceneTarget() = default;
  SceneTarget(const SceneTarget&) = delete;
  SceneTarget& operator=(const SceneTarget&) = delete;
  ~SceneTarget();

  /// (Re)allocates for the size and sample count when they changed; binds it for drawing.
  void Bind(int width, int height, int samples);
  /// Copies (and averages the samples) into `framebuffer`, bound for drawing afterwards.
  void ResolveInto(unsigned framebuffer) const;
  int samples() const { return samples_; }
  unsigned framebuffer() const { return framebuffer_; }

 private:
  void Free();

  unsigned framebuffer_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0, samples_ = 0;
};

/// A one-sample RGBA8 colour texture with its framebuffer: the image a post-process pass (FXAA)
/// reads, with linear filtering and clamped edges.
class ColorTexture {
 public:
  ColorTexture() = default;
  ColorTexture(const ColorTexture&) = delete;
  ColorTexture& operator=(const ColorTexture&) = delete;
  ~ColorTexture();

  /// (Re)allocates for the size when it changed.
  void Resize(int width, int height);
  unsigned framebuffer() const { return framebuffer_; }
  /// Binds the colour texture to texture unit `unit`.
  void BindTexture(int unit) const;

 private:
  unsigned framebuffer_ = 0, texture_ = 0;
  int width_ = 0, height_ = 0;
};

/// A square depth texture with hardware depth comparison (sampler2DShadow, linear = 2x2 PCF).
class ShadowMap {
 public:
  ShadowMap() = default;
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;
  ~ShadowMap();

  /// Allocates on first use or size change, binds it for drawing and clears the depth.
  void BeginPass(int size);
  /// Binds the depth texture to texture unit `unit`.
  void BindTexture(int unit) const;
  int size() const { return size_; }

 private:
  unsigned framebuffer_ = 0, texture_ = 0;
  int size_ = 0;
};

}  // namespace lamina::ui
