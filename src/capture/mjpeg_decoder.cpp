// SPDX-License-Identifier: Apache-2.0
#include "capture/mjpeg_decoder.hpp"

#include <cstring>

#include "core/image.hpp"

namespace rays::capture {

int choose_jpeg_scale(int crop_w, int crop_h) {
    for (int d = 8; d > 1; d /= 2)
        if (crop_w >= kFrameSize * d && crop_h >= kFrameSize * d) return d;
    return 1;
}

MjpegDecoder::MjpegDecoder() {
    jpeg_.err = jpeg_std_error(&error_.jpeg);
    error_.jpeg.error_exit = on_error;
    error_.jpeg.emit_message = on_message;
    jpeg_create_decompress(&jpeg_);
}

MjpegDecoder::~MjpegDecoder() { jpeg_destroy_decompress(&jpeg_); }

// libjpeg must not return after a fatal error: jump back into decode().
void MjpegDecoder::on_error(j_common_ptr info) {
    auto* error = reinterpret_cast<ErrorManager*>(info->err);
    info->err->format_message(info, error->message);
    std::longjmp(error->jump, 1);
}

// Level −1 is a warning about damaged data; higher levels are trace output. Nothing is printed.
void MjpegDecoder::on_message(j_common_ptr info, int level) {
    auto* error = reinterpret_cast<ErrorManager*>(info->err);
    if (level >= 0 || error->warned) return;
    error->warned = true;
    info->err->format_message(info, error->message);
}

void MjpegDecoder::configure(int width, int height, int scale_denom, int rows_needed) {
    width_ = width;
    height_ = height;
    scale_denom_ = scale_denom;
    decoded_width_ = (width + scale_denom - 1) / scale_denom;  // as libjpeg rounds
    decoded_height_ = (height + scale_denom - 1) / scale_denom;
    rows_needed_ = rows_needed;
    const std::size_t plane = static_cast<std::size_t>(decoded_width_) * static_cast<std::size_t>(rows_needed_);
    luma_.assign(plane, 0);
    cb_.assign(plane, 128);
    cr_.assign(plane, 128);
    ycc_row_.assign(3 * static_cast<std::size_t>(decoded_width_), 0);
}

bool MjpegDecoder::fail(const char* why) {
    jpeg_abort_decompress(&jpeg_);
    std::snprintf(error_.message, sizeof error_.message, "%s", why);
    return false;
}

// Only members change between setjmp and a longjmp back to it, so no local is left indeterminate.
bool MjpegDecoder::decode(const std::uint8_t* data, std::size_t size) {
    error_.warned = false;
    error_.message[0] = '\0';
    if (setjmp(error_.jump) != 0) {
        jpeg_abort_decompress(&jpeg_);
        return false;
    }
    jpeg_mem_src(&jpeg_, data, static_cast<unsigned long>(size));
    if (jpeg_read_header(&jpeg_, TRUE) != JPEG_HEADER_OK) return fail("no image in the JPEG data");
    if (static_cast<int>(jpeg_.image_width) != width_ || static_cast<int>(jpeg_.image_height) != height_)
        return fail("JPEG frame size differs from the negotiated size");
    colour_ = jpeg_.jpeg_color_space == JCS_YCbCr && jpeg_.num_components == 3;
    jpeg_.out_color_space = colour_ ? JCS_YCbCr : JCS_GRAYSCALE;
    jpeg_.do_fancy_upsampling = FALSE;
    jpeg_.scale_num = 1;
    jpeg_.scale_denom = static_cast<unsigned int>(scale_denom_);
    jpeg_start_decompress(&jpeg_);
    if (static_cast<int>(jpeg_.output_width) != decoded_width_ || jpeg_.output_components != (colour_ ? 3 : 1))
        return fail("unexpected decoded layout");
    const auto w = static_cast<std::size_t>(decoded_width_);
    while (static_cast<int>(jpeg_.output_scanline) < rows_needed_) {
        const std::size_t at = static_cast<std::size_t>(jpeg_.output_scanline) * w;
        JSAMPROW row = colour_ ? ycc_row_.data() : luma_.data() + at;
        jpeg_read_scanlines(&jpeg_, &row, 1);
        if (!colour_) continue;
        for (std::size_t x = 0; x < w; ++x) {
            luma_[at + x] = ycc_row_[3 * x];
            cb_[at + x] = ycc_row_[3 * x + 1];
            cr_[at + x] = ycc_row_[3 * x + 2];
        }
    }
    if (jpeg_.output_scanline < jpeg_.output_height) jpeg_abort_decompress(&jpeg_);  // rows below the crop
    else jpeg_finish_decompress(&jpeg_);
    return !error_.warned;
}

}  // namespace rays::capture
