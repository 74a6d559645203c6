// SPDX-License-Identifier: Apache-2.0
// Turns one captured buffer (GREY, YUYV or MJPEG, any size) into the 128×128 processing frame: the
// crop's luma, area-averaged, and for YUYV and colour MJPEG the same area's chroma at 64×64. Buffers
// are sized in configure(); convert() allocates nothing outside libjpeg.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "capture/mjpeg_decoder.hpp"
#include "capture/pixel_format.hpp"
#include "core/image.hpp"
#include "io/area_scaler.hpp"
#include "io/chroma_scaler.hpp"

namespace rays::capture {

// How a captured buffer is laid out, as negotiated with the driver.
struct FrameLayout {
    PixelFormat format = PixelFormat::Grey;
    int width = 0;
    int height = 0;
    int bytes_per_line = 0;  // raw formats: the row pitch
};

// Processing pixel → source pixel, centres at integers: source = processing · scale + offset.
struct SourceMapping {
    double scale_x = 1.0;
    double scale_y = 1.0;
    double offset_x = 0.0;
    double offset_y = 0.0;
};

class FrameConverter {
public:
    // crop is in source pixels (w = 0: the whole frame). False with error when it does not fit.
    bool configure(const FrameLayout& layout, io::Crop crop, std::string& error);

    // False when the buffer does not hold a whole, clean frame; failure() says why.
    bool convert(const std::uint8_t* data, std::size_t bytes, GreyImage& out, Chroma& chroma);

    const SourceMapping& mapping() const { return mapping_; }
    int jpeg_scale_denom() const { return layout_.format == PixelFormat::Mjpeg ? jpeg_.scale_denom() : 1; }
    const char* failure() const { return failure_; }

private:
    bool configure_mjpeg(io::Crop crop, std::string& error);
    int chroma_width() const;  // YUYV's chroma planes: one Cb and one Cr per pair of pixels
    void split_yuyv(const std::uint8_t* data);
    void set_mapping(io::Crop source_crop);

    FrameLayout layout_;
    std::size_t raw_bytes_ = 0;           // raw formats: the least a whole frame needs
    io::Crop crop_;                        // in source pixels, whole frame resolved
    std::optional<io::AreaScaler> scaler_;  // over what convert() hands it: buffer, luma_ or decoded luma
    std::optional<io::ChromaScaler> chroma_;  // YUYV: over u_ and v_; MJPEG: over the decoded Cb and Cr
    std::vector<std::uint8_t> luma_;       // YUYV: the crop's luma
    std::vector<std::uint8_t> u_;          // YUYV: the frame's Cb and Cr planes (half width), the crop's rows filled
    std::vector<std::uint8_t> v_;
    MjpegDecoder jpeg_;
    SourceMapping mapping_;
    const char* failure_ = "";
};

}  // namespace rays::capture
