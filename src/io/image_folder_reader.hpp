// SPDX-License-Identifier: Apache-2.0
// Reads a folder of .pgm and .png images as a sequence, in file name order. All must have one size.
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/frame_reader.hpp"
#include "io/png_decoder.hpp"

namespace rays::io {

class ImageFolderReader final : public FrameReader {
public:
    // Lists the folder and decodes the first image for the frame size. Null + error on failure.
    static std::unique_ptr<ImageFolderReader> open(const std::string& dir, std::string& error);

    // Decoding allocates inside libpng and stdio per file; use YUV4MPEG2 where that matters.
    Status next(SourceImage& out) override;
    const std::string& error() const override { return error_; }
    int width() const override { return first_.width; }
    int height() const override { return first_.height; }
    double fps() const override { return 0.0; }

    std::size_t frame_count() const { return files_.size(); }

private:
    explicit ImageFolderReader(std::vector<std::filesystem::path> files);
    bool decode(const std::filesystem::path& file, SourceImage& out, std::string& error);

    std::vector<std::filesystem::path> files_;
    std::size_t next_index_ = 0;
    SourceImage first_;  // decoded at open; handed over by the first next()
    PngDecoder png_;
    Status sticky_ = Status::Frame;
    std::string error_;
};

}  // namespace rays::io
