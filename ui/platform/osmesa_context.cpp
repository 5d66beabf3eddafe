// SPDX-License-Identifier: MIT
// OSMesa context creation (OSMesaCreateContextAttribs, core profile 3.3).
#include "ui/platform/osmesa_context.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>

namespace lamina::ui {

namespace {

constexpr int kMaxSize = 16384;  // OSMESA_MAX_WIDTH / HEIGHT of Mesa 22

}  // namespace

OsmesaContext::~OsmesaContext() {
  if (context_ != nullptr) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

bool OsmesaContext::Create(int width, int height, std::string* error) {
  if (width <= 0 || height <= 0 || width > kMaxSize || height > kMaxSize) {
    *error = "OSMesa buffer size must be 1..16384 pixels per side, got " + std::to_string(width) +
             "x" + std::to_string(height);
    return false;
  }
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            8,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context_ == nullptr) {
    *error = "OSMesaCreateContextAttribs refused an OpenGL 3.3 core context";
    return false;
  }
  if (!Resize(width, height)) {
    *error = "OSMesaMakeCurrent failed";
    return false;
  }
  return true;
}

bool OsmesaContext::Resize(int width, int height) {
  if (width <= 0 || height <= 0 || width > kMaxSize || height > kMaxSize) return false;
  buffer_.assign(static_cast<size_t>(width) * height * 4, 0);
  width_ = width;
  height_ = height;
  return MakeCurrent();
}

bool OsmesaContext::MakeCurrent() {
  return context_ != nullptr &&
         OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE,
                           width_, height_) == GL_TRUE;
}

void OsmesaContext::SwapOrFinish() {
  glFinish();
}

}  // namespace lamina::ui
