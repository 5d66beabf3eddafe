// SPDX-License-Identifier: MIT
// PNG reading/writing (stb) and the pixel comparison of the golden-image tests.
#include "tests/render/golden_image.h"

#include <algorithm>
#include <cstdlib>

#include <stb_image.h>
#include <stb_image_write.h>

namespace lamina::test {

bool ReadPng(const std::string& path, Image* image) {
  int channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &image->width, &image->height, &channels, 4);
  if (data == nullptr) return false;
  image->rgba.assign(data, data + static_cast<size_t>(image->width) * image->height * 4);
  stbi_image_free(data);
  return true;
}

bool WritePng(const std::string& path, const Image& image) {
  return stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(),
                        image.width * 4) != 0;
}

Image FromBottomUp(int width, int height, const std::vector<std::uint8_t>& rgba) {
  Image image{width, height, std::vector<std::uint8_t>(rgba.size())};
  const size_t stride = static_cast<size_t>(width) * 4;
  for (int row = 0; row < height; ++row) {
    std::copy_n(rgba.begin() + static_cast<std::ptrdiff_t>((height - 1 - row) * stride), stride,
                image.rgba.begin() + static_cast<std::ptrdiff_t>(row * stride));
  }
  return image;
}

ImageDifference CompareImages(const Image& expected, const Image& actual, int threshold) {
  ImageDifference result;
  result.diff = expected;
  const size_t pixels = static_cast<size_t>(expected.width) * expected.height;
  for (size_t p = 0; p < pixels; ++p) {
    int largest = 0;
    for (int c = 0; c < 3; ++c) {
      largest = std::max(largest, std::abs(expected.rgba[p * 4 + c] - actual.rgba[p * 4 + c]));
    }
    result.max_channel_difference = std::max(result.max_channel_difference, largest);
    std::uint8_t* out = &result.diff.rgba[p * 4];
    const std::uint8_t grey = static_cast<std::uint8_t>((out[0] + out[1] + out[2]) / 6 + 64);
    const bool differs = largest > threshold;
    result.differing_pixels += differs ? 1 : 0;
    out[0] = differs ? 255 : grey;
    out[1] = differs ? 0 : grey;
    out[2] = differs ? 0 : grey;
    out[3] = 255;
  }
  result.differing_fraction =
      pixels > 0 ? static_cast<double>(result.differing_pixels) / pixels : 0;
  return result;
}

}  // namespace lamina::test
