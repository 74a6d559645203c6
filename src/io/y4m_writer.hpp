// SPDX-License-Identifier: Apache-2.0
// Writes 8-bit grey frames as a mono YUV4MPEG2 stream ("YUV4MPEG2 W128 H128 F25:1 Ip A1:1 Cmono").
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

#include "io/stdio_file.hpp"

namespace rays::io {

class Y4mWriter {
public:
    // Creates path ("-" for stdout) and writes the header. Returns false with error() set.
    bool open(const std::string& path, int width, int height, int fps_num, int fps_den);
    // Appends one frame of width·height bytes, row-major, and flushes it so a live reader sees it.
    bool write(const std::uint8_t* grey);
    // Flushes and closes; also done by the destructor, which cannot report failure.
    bool close();

    bool is_open() const { return file_ != nullptr; }
    int frames_written() const { return frames_written_; }
    const std::string& error() const { return error_; }

private:
    bool fail(const std::string& what);

    StdioFile owned_;  // null for stdout
    std::FILE* file_ = nullptr;
    std::string path_;
    int width_ = 0;
    int height_ = 0;
    int frames_written_ = 0;
    std::string error_;
};

}  // namespace rays::io
