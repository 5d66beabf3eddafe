// SPDX-License-Identifier: MIT
#include "core/io/lzf.h"

#include <algorithm>

namespace lamina::core {

namespace {

// The decoder's position in both buffers; every step checks its bounds first.
class LzfDecoder {
 public:
  LzfDecoder(const std::uint8_t* in, std::size_t in_size, std::size_t expected_size,
             std::vector<std::uint8_t>* out)
      : in_(in), in_size_(in_size), expected_(expected_size), out_(out) {}

  bool Run(std::string* error) {
    while (next_ < in_size_) {
      const unsigned control = in_[next_++];
      const bool ok = control < 32 ? Literal(control + 1, error) : Reference(control, error);
      if (!ok) return false;
    }
    if (out_->size() == expected_) return true;
    *error = "decompressed to " + std::to_string(out_->size()) + " bytes, expected " +
             std::to_string(expected_);
    return false;
  }

 private:
  bool Literal(std::size_t length, std::string* error) {
    if (length > in_size_ - next_) return Fail("a literal run passes the end of the data", error);
    if (length > expected_ - out_->size()) return Fail("the data decompresses too long", error);
    out_->insert(out_->end(), in_ + next_, in_ + next_ + length);
    next_ += length;
    return true;
  }

  bool Reference(unsigned control, std::string* error) {
    std::size_t length = control >> 5;
    if (length == 7 && !Take(&length, error)) return false;
    std::size_t low = 0;
    if (!Take(&low, error)) return false;
    length += 2;
    const std::size_t back = ((control & 31u) << 8) + low + 1;
    if (back > out_->size()) return Fail("a back reference points before the start", error);
    if (length > expected_ - out_->size()) return Fail("the data decompresses too long", error);
    // byte by byte: the reference may overlap the bytes it writes
    for (std::size_t i = 0; i < length; ++i) out_->push_back((*out_)[out_->size() - back]);
    return true;
  }

  // adds the next input byte to *value
  bool Take(std::size_t* value, std::string* error) {
    if (next_ >= in_size_) return Fail("a back reference passes the end of the data", error);
    *value += in_[next_++];
    return true;
  }

  static bool Fail(const char* reason, std::string* error) {
    *error = reason;
    return false;
  }

  const std::uint8_t* in_;
  std::size_t in_size_;
  std::size_t expected_;
  std::vector<std::uint8_t>* out_;
  std::size_t next_ = 0;
};

}  // namespace

bool LzfDecompress(const std::uint8_t* in, std::size_t in_size, std::size_t expected_size,
                   std::vector<std::uint8_t>* out, std::string* error) {
  out->clear();
  // no LZF block expands more than 88 times (3 bytes for a 264-byte reference)
  out->reserve(std::min(expected_size, in_size * 88 + 32));
  return LzfDecoder(in, in_size, expected_size, out).Run(error);
}

}  // namespace lamina::core
