// SPDX-License-Identifier: Apache-2.0
#include "io/y4m_writer.hpp"

#include <cerrno>
#include <cstring>

#include "io/y4m_header.hpp"

namespace rays::io {

bool Y4mWriter::fail(const std::string& what) {
    error_ = path_ + ": " + what;
    return false;
}

bool Y4mWriter::open(const std::string& path, int width, int height, int fps_num, int fps_den) {
    close();
    path_ = path;
    frames_written_ = 0;
    if (width < 1 || height < 1 || width > kMaxY4mSide || height > kMaxY4mSide || fps_num < 1 || fps_den < 1)
        return fail("bad stream parameters " + std::to_string(width) + "x" + std::to_string(height) + " at " +
                    std::to_string(fps_num) + ":" + std::to_string(fps_den) + " fps");
    if (path == "-") {
        file_ = stdout;
    } else {
        owned_.reset(std::fopen(path.c_str(), "wb"));
        if (!owned_) return fail(std::string("cannot create: ") + std::strerror(errno));
        file_ = owned_.get();
    }
    width_ = width;
    height_ = height;
    if (std::fprintf(file_, "YUV4MPEG2 W%d H%d F%d:%d Ip A1:1 Cmono\n", width, height, fps_num, fps_den) < 0)
        return fail(std::string("cannot write header: ") + std::strerror(errno));
    return true;
}

bool Y4mWriter::write(const std::uint8_t* grey) {
    if (!file_) return fail("write on a closed stream");
    const std::size_t bytes = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    if (std::fputs("FRAME\n", file_) < 0 || std::fwrite(grey, 1, bytes, file_) != bytes || std::fflush(file_) != 0) {
        const int err = errno;
        return fail("cannot write frame " + std::to_string(frames_written_) + ": " + std::strerror(err));
    }
    ++frames_written_;
    return true;
}

bool Y4mWriter::close() {
    if (!file_) return true;
    const bool ok = owned_ ? std::fclose(owned_.release()) == 0 : std::fflush(file_) == 0;
    file_ = nullptr;
    return ok || fail(std::string("cannot close: ") + std::strerror(errno));
}

}  // namespace rays::io
