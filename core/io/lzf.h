// SPDX-License-Identifier: MIT
// LZF decompression (Marc Lehmann's liblzf format), the codec of PCL's `DATA binary_compressed`.
// A stream of blocks, each starting with a control byte c:
//  - c < 32: a literal run, the next c + 1 bytes are copied;
//  - else a back reference of length (c >> 5) + 2 (when c >> 5 == 7 the next byte adds to it)
//    to the output ((c & 31) << 8) + next byte + 1 bytes back; it may overlap what it writes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lamina::core {

/// Decompresses `in` (`in_size` bytes) into `out`, which receives exactly `expected_size` bytes.
/// Returns false, with a reason in `error`, when the data is corrupt: a run past the end of
/// the input or past `expected_size`, a reference before the start of the output, or an output
/// of another size. Never reads or writes out of bounds.
bool LzfDecompress(const std::uint8_t* in, std::size_t in_size, std::size_t expected_size,
                   std::vector<std::uint8_t>* out, std::string* error);

}  // namespace lamina::core
