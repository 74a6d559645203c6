// SPDX-License-Identifier: Apache-2.0
// Reads a YUV4MPEG2 stream frame by frame as data arrives (file, FIFO or stdin; never seeks): the luma
// plane and, for 8-bit colour streams, the Cb and Cr planes (an alpha plane is skipped).
#pragma once
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "io/frame_reader.hpp"
#include "io/stdio_file.hpp"
#include "io/y4m_header.hpp"

namespace rays::io {

class Y4mReader final : public FrameReader {
public:
    // Opens path and reads its header (blocks on a FIFO until the writer sends it). Null + error on failure.
    static std::unique_ptr<Y4mReader> open(const std::string& path, std::string& error);
    // Reads from the process's stdin, which stays open afterwards.
    static std::unique_ptr<Y4mReader> open_stdin(std::string& error);

    Status next(SourceImage& out) override;
    const std::string& error() const override { return error_; }
    int width() const override { return header_.width; }
    int height() const override { return header_.height; }
    double fps() const override { return header_.fps(); }
    int chroma_width() const override { return header_.chroma_width(); }
    int chroma_height() const override { return header_.chroma_height(); }

    const Y4mHeader& header() const { return header_; }
    int frames_read() const { return frames_read_; }

private:
    Y4mReader(StdioFile owned, std::FILE* file, std::string name);
    static std::unique_ptr<Y4mReader> start(std::unique_ptr<Y4mReader> reader, std::string& error);

    bool read_header(std::string& error);
    Status read_frame_marker();
    // Reads n bytes into dst; on a short read reports the truncation with `done` bytes already read.
    bool read_exact(std::uint8_t* dst, std::size_t n, std::size_t& done);
    bool read_luma(SourceImage& out, std::size_t& done);
    bool read_chroma(SourceImage& out, std::size_t& done);
    std::string frame_label() const;
    Status fail(std::string message);

    StdioFile owned_;     // null for stdin
    std::FILE* file_;     // the stream read from (owned_ or stdin)
    std::string name_;    // for messages
    Y4mHeader header_;
    std::vector<std::uint8_t> scratch_;  // alpha being skipped, or 16-bit luma rows
    int frames_read_ = 0;
    Status sticky_ = Status::Frame;      // End or Error once reached
    std::string error_;
};

}  // namespace rays::io
