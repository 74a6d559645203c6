// SPDX-License-Identifier: Apache-2.0
// MJPEG frames through libjpeg-turbo, decoded at a reduced DCT scale 1/d (the IDCT then yields d×
// smaller blocks directly): the luma and, for a colour JPEG, Cb and Cr at the decoded luma's size
// (libjpeg's plain replicating upsampling; they are area-averaged to 64×64 afterwards anyway).
// libjpeg-turbo allocates inside each decode, so this runs on the capture side, not in the frame loop.
#pragma once
#include <csetjmp>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <jpeglib.h>

namespace rays::capture {

// The largest reduction d (8, 4, 2 or 1: libjpeg-turbo's SIMD-accelerated scales) that still leaves a
// crop_w × crop_h crop at least 128 decoded pixels in both axes.
int choose_jpeg_scale(int crop_w, int crop_h);

class MjpegDecoder {
public:
    MjpegDecoder();
    ~MjpegDecoder();
    MjpegDecoder(const MjpegDecoder&) = delete;  // libjpeg keeps a pointer to error_
    MjpegDecoder& operator=(const MjpegDecoder&) = delete;

    // Frames will be width × height; decode at 1/scale_denom and stop after the first rows_needed
    // decoded rows. Sizes the planes' buffers (the only allocations outside libjpeg).
    void configure(int width, int height, int scale_denom, int rows_needed);

    // Decodes one frame's luma (and chroma, where it has colour). False when the data is not a clean JPEG of the configured size
    // (libjpeg's warnings, e.g. a truncated frame, count as unclean); failure() then says why.
    bool decode(const std::uint8_t* data, std::size_t size);

    const std::uint8_t* luma() const { return luma_.data(); }  // rows of decoded_width() bytes
    bool colour() const { return colour_; }                    // the last frame had Cb and Cr
    const std::uint8_t* cb() const { return cb_.data(); }      // as luma(), while colour()
    const std::uint8_t* cr() const { return cr_.data(); }
    int decoded_width() const { return decoded_width_; }
    int decoded_height() const { return decoded_height_; }
    int scale_denom() const { return scale_denom_; }
    const char* failure() const { return error_.message; }

private:
    struct ErrorManager {
        jpeg_error_mgr jpeg;  // first, so libjpeg's pointer to it is a pointer to the whole
        std::jmp_buf jump;
        bool warned = false;
        char message[JMSG_LENGTH_MAX] = {};
    };
    static void on_error(j_common_ptr info);
    static void on_message(j_common_ptr info, int level);
    bool fail(const char* why);

    ErrorManager error_;
    jpeg_decompress_struct jpeg_{};
    int width_ = 0;
    int height_ = 0;
    int scale_denom_ = 1;
    int rows_needed_ = 0;
    int decoded_width_ = 0;
    int decoded_height_ = 0;
    std::vector<std::uint8_t> luma_;
    std::vector<std::uint8_t> cb_;
    std::vector<std::uint8_t> cr_;
    std::vector<std::uint8_t> ycc_row_;  // one decoded row, Y Cb Cr interleaved
    bool colour_ = false;
};

}  // namespace rays::capture
