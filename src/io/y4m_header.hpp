// SPDX-License-Identifier: Apache-2.0
// The YUV4MPEG2 stream header: "YUV4MPEG2 W<w> H<h> F<a>:<b> I<i> A<a>:<b> C<colour> X<ext>...".
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace rays::io {

inline constexpr int kMaxY4mSide = 8192;

// Sample layouts whose luma plane we can take. Mono16 is 16-bit little-endian luma (as ffmpeg writes
// gray16le); we keep its high byte.
enum class Y4mColour { Mono, Mono16, C420, C411, C422, C444, C444Alpha };

struct Y4mHeader {
    int width = 0;
    int height = 0;
    int fps_num = 0;  // 0 when the stream does not say (F absent or F0:0)
    int fps_den = 0;
    Y4mColour colour = Y4mColour::C420;  // the format's default when C is absent

    double fps() const;
    std::size_t luma_bytes() const;    // bytes of the Y plane in one frame
    std::size_t chroma_bytes() const;  // bytes after the Y plane (Cb, Cr, alpha)
    int chroma_width() const;          // of the Cb and Cr planes; 0 for mono
    int chroma_height() const;
    std::size_t frame_bytes() const { return luma_bytes() + chroma_bytes(); }
};

// Parses one header line without its '\n'. Returns false with a one-line reason.
bool parse_y4m_header(std::string_view line, Y4mHeader& out, std::string& error);

}  // namespace rays::io
