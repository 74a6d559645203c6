// SPDX-License-Identifier: Apache-2.0
// Netpbm greymaps: P5 (binary, 8- or 16-bit big-endian) and P2 (ASCII), scaled to 8 bits.
#pragma once
#include <string>

#include "io/source_image.hpp"

namespace rays::io {

// Decodes the file into out (reusing its buffer). Returns false with a one-line reason.
bool read_pgm(const std::string& path, SourceImage& out, std::string& error);

}  // namespace rays::io
