// SPDX-License-Identifier: MIT
// Golden-image comparison for the render tests: a pixel differs when any channel differs by more
// than a threshold; an image matches when few enough pixels differ. On a mismatch the actual
// image and a diff image are written next to the test.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lamina::test {

/// An RGBA8 image, top row first.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

/// Reads a PNG as RGBA8; false when missing or unreadable.
bool ReadPng(const std::string& path, Image* image);
/// Writes an Image as PNG.
bool WritePng(const std::string& path, const Image& image);
/// Flips OpenGL's bottom-up rows into an Image.
Image FromBottomUp(int width, int height, const std::vector<std::uint8_t>& rgba);

struct ImageDifference {
  int differing_pixels = 0;
  int max_channel_difference = 0;
  double differing_fraction = 0.0;
  Image diff;  ///< grey copy of the expected image with differing pixels in red
};

/// Compares same-sized images; a pixel differs when a channel differs by more than `threshold`.
ImageDifference CompareImages(const Image& expected, const Image& actual, int threshold);

}  // namespace lamina::test
