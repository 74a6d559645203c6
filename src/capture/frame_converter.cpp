// SPDX-License-Identifier: Apache-2.0
#include "capture/frame_converter.hpp"

#include <algorithm>

namespace rays::capture {

bool FrameConverter::configure(const FrameLayout& layout, io::Crop crop, std::string& error) {
    layout_ = layout;
    const auto whole = io::AreaScaler::make(layout.width, layout.height, crop, error);
    if (!whole) return false;
    crop_ = whole->crop();
    set_mapping(crop_);
    const auto pitch = static_cast<std::size_t>(layout.bytes_per_line);
    switch (layout.format) {
        case PixelFormat::Grey:
            raw_bytes_ = pitch * static_cast<std::size_t>(layout.height - 1) + static_cast<std::size_t>(layout.width);
            scaler_ = whole;  // reads the buffer in place
            return true;
        case PixelFormat::Yuyv:
            raw_bytes_ = pitch * static_cast<std::size_t>(layout.height - 1) + 2 * static_cast<std::size_t>(layout.width);
            luma_.assign(static_cast<std::size_t>(crop_.w) * static_cast<std::size_t>(crop_.h), 0);
            u_.assign(static_cast<std::size_t>(chroma_width()) * static_cast<std::size_t>(layout.height), 128);
            v_.assign(u_.size(), 128);
            scaler_ = io::AreaScaler::make(crop_.w, crop_.h, io::Crop{}, error);
            chroma_ = io::ChromaScaler::make(layout.width, layout.height, chroma_width(), layout.height, crop_, error);
            return scaler_.has_value() && chroma_.has_value();
        case PixelFormat::Mjpeg: return configure_mjpeg(crop_, error);
    }
    return false;
}

// The crop grows outwards to whole decoded pixels; the mapping follows what is actually averaged.
bool FrameConverter::configure_mjpeg(io::Crop crop, std::string& error) {
    const int d = choose_jpeg_scale(crop.w, crop.h);
    const int decoded_w = (layout_.width + d - 1) / d;
    const int decoded_h = (layout_.height + d - 1) / d;
    const int x0 = crop.x / d;
    const int y0 = crop.y / d;
    const int x1 = std::min(decoded_w, (crop.x + crop.w + d - 1) / d);
    const int y1 = std::min(decoded_h, (crop.y + crop.h + d - 1) / d);
    jpeg_.configure(layout_.width, layout_.height, d, y1);
    const io::Crop decoded_crop{x0, y0, x1 - x0, y1 - y0};
    scaler_ = io::AreaScaler::make(decoded_w, decoded_h, decoded_crop, error);
    chroma_ = io::ChromaScaler::make(decoded_w, decoded_h, decoded_w, decoded_h, decoded_crop, error);
    set_mapping(io::Crop{x0 * d, y0 * d, (x1 - x0) * d, (y1 - y0) * d});
    return scaler_.has_value() && chroma_.has_value();
}

// As AreaScaler's convention: scale = crop / 128, offset = crop origin + (scale − 1) / 2.
void FrameConverter::set_mapping(io::Crop source_crop) {
    mapping_.scale_x = static_cast<double>(source_crop.w) / kFrameSize;
    mapping_.scale_y = static_cast<double>(source_crop.h) / kFrameSize;
    mapping_.offset_x = source_crop.x + (mapping_.scale_x - 1.0) / 2.0;
    mapping_.offset_y = source_crop.y + (mapping_.scale_y - 1.0) / 2.0;
}

int FrameConverter::chroma_width() const { return std::max(1, layout_.width / 2); }

bool FrameConverter::convert(const std::uint8_t* data, std::size_t bytes, GreyImage& out, Chroma& chroma) {
    failure_ = "";
    chroma.present = false;
    switch (layout_.format) {
        case PixelFormat::Grey:
            if (bytes < raw_bytes_) break;
            scaler_->scale(data, layout_.bytes_per_line, out);
            return true;
        case PixelFormat::Yuyv: {
            if (bytes < raw_bytes_) break;
            split_yuyv(data);
            scaler_->scale(luma_.data(), crop_.w, out);
            chroma_->scale(u_.data(), v_.data(), chroma_width(), chroma);
            return true;
        }
        case PixelFormat::Mjpeg:
            if (!jpeg_.decode(data, bytes)) {
                failure_ = jpeg_.failure();
                return false;
            }
            scaler_->scale(jpeg_.luma(), jpeg_.decoded_width(), out);
            if (jpeg_.colour()) chroma_->scale(jpeg_.cb(), jpeg_.cr(), jpeg_.decoded_width(), chroma);
            return true;
    }
    failure_ = "short frame";
    return false;
}

// Y0 U Y1 V: the crop's luma (every even byte) into luma_, and the chroma pairs its rows touch into u_
// and v_ at their place in the half-width planes.
void FrameConverter::split_yuyv(const std::uint8_t* data) {
    const int first_pair = crop_.x / 2, end_pair = std::min((crop_.x + crop_.w + 1) / 2, layout_.width / 2);
    const auto cw = static_cast<std::ptrdiff_t>(chroma_width());
    for (int r = 0; r < crop_.h; ++r) {
        const std::uint8_t* line = data + static_cast<std::ptrdiff_t>(crop_.y + r) * layout_.bytes_per_line;
        const std::uint8_t* src = line + 2 * crop_.x;
        std::uint8_t* dst = luma_.data() + static_cast<std::ptrdiff_t>(r) * crop_.w;
        for (int i = 0; i < crop_.w; ++i) dst[i] = src[2 * i];
        std::uint8_t* u = u_.data() + (crop_.y + r) * cw;
        std::uint8_t* v = v_.data() + (crop_.y + r) * cw;
        for (int p = first_pair; p < end_pair; ++p) {
            u[p] = line[4 * p + 1];
            v[p] = line[4 * p + 3];
        }
    }
}

}  // namespace rays::capture
