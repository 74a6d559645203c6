// SPDX-License-Identifier: Apache-2.0
#include "io/y4m_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

namespace rays::io {
namespace {

constexpr std::size_t kMaxHeaderBytes = 4096;       // ffmpeg's headers are about 100 bytes
constexpr std::size_t kMaxFrameParamBytes = 1024;   // "FRAME" parameters up to '\n'
constexpr std::size_t kSkipChunkBytes = 64 * 1024;  // alpha is discarded through a buffer this big

}  // namespace

Y4mReader::Y4mReader(StdioFile owned, std::FILE* file, std::string name)
    : owned_(std::move(owned)), file_(file), name_(std::move(name)) {}

std::unique_ptr<Y4mReader> Y4mReader::open(const std::string& path, std::string& error) {
    StdioFile file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        error = path + ": cannot open: " + std::strerror(errno);
        return nullptr;
    }
    std::FILE* stream = file.get();
    return start(std::unique_ptr<Y4mReader>(new Y4mReader(std::move(file), stream, path)), error);
}

std::unique_ptr<Y4mReader> Y4mReader::open_stdin(std::string& error) {
    return start(std::unique_ptr<Y4mReader>(new Y4mReader(nullptr, stdin, "stdin")), error);
}

std::unique_ptr<Y4mReader> Y4mReader::start(std::unique_ptr<Y4mReader> reader, std::string& error) {
    if (!reader->read_header(error)) {
        error = reader->name_ + ": " + error;
        return nullptr;
    }
    const std::size_t row16 = 2 * static_cast<std::size_t>(reader->header_.width);
    reader->scratch_.resize(std::max(kSkipChunkBytes, row16));
    return reader;
}

bool Y4mReader::read_header(std::string& error) {
    std::string line;
    for (int c = std::getc(file_); c != '\n'; c = std::getc(file_)) {
        if (c == EOF) {
            error = line.empty() ? "empty stream: no YUV4MPEG2 header" : "header not terminated by a newline";
            return false;
        }
        if (line.size() == kMaxHeaderBytes) {
            error = "header longer than " + std::to_string(kMaxHeaderBytes) + " bytes";
            return false;
        }
        line.push_back(static_cast<char>(c));
    }
    return parse_y4m_header(line, header_, error);
}

// Frames are counted from 0, as in the scenes' gt.csv.
std::string Y4mReader::frame_label() const { return "frame " + std::to_string(frames_read_); }

Y4mReader::Status Y4mReader::fail(std::string message) {
    error_ = name_ + ": " + std::move(message);
    sticky_ = Status::Error;
    return Status::Error;
}

// Each frame starts with "FRAME", optional parameters, then '\n'. End of stream here is a clean End.
Y4mReader::Status Y4mReader::read_frame_marker() {
    static constexpr char kMarker[] = "FRAME";
    for (std::size_t i = 0; i < sizeof kMarker - 1; ++i) {
        const int c = std::getc(file_);
        const int err = errno;
        if (c == EOF && i == 0 && !std::ferror(file_)) {
            sticky_ = Status::End;
            return Status::End;
        }
        if (c == EOF)
            return fail(std::ferror(file_) ? "read error before " + frame_label() + ": " + std::strerror(err)
                                           : "truncated FRAME marker of " + frame_label());
        if (c != kMarker[i]) return fail("bad FRAME marker before " + frame_label());
    }
    for (std::size_t n = 0;; ++n) {
        const int c = std::getc(file_);
        if (c == '\n') return Status::Frame;
        if (c == EOF) return fail("truncated FRAME marker of " + frame_label());
        if (n == 0 && c != ' ') return fail("bad FRAME marker before " + frame_label());
        if (n == kMaxFrameParamBytes) return fail("FRAME parameters of " + frame_label() + " too long");
    }
}

bool Y4mReader::read_exact(std::uint8_t* dst, std::size_t n, std::size_t& done) {
    const std::size_t got = std::fread(dst, 1, n, file_);
    const int err = errno;
    done += got;
    if (got == n) return true;
    const std::string frame = frame_label();
    if (std::ferror(file_))
        fail("read error in " + frame + ": " + std::strerror(err));
    else
        fail("truncated " + frame + ": expected " + std::to_string(header_.frame_bytes()) + " bytes, got " +
             std::to_string(done));
    return false;
}

bool Y4mReader::read_luma(SourceImage& out, std::size_t& done) {
    const std::size_t pixels = static_cast<std::size_t>(header_.width) * static_cast<std::size_t>(header_.height);
    out.width = header_.width;
    out.height = header_.height;
    out.grey.resize(pixels);  // no allocation once out has held a frame of this size
    if (header_.colour != Y4mColour::Mono16) return read_exact(out.grey.data(), pixels, done);
    // 16-bit little-endian samples: keep the high byte.
    const std::size_t w = static_cast<std::size_t>(header_.width);
    for (std::size_t y = 0; y < static_cast<std::size_t>(header_.height); ++y) {
        if (!read_exact(scratch_.data(), 2 * w, done)) return false;
        for (std::size_t x = 0; x < w; ++x) out.grey[y * w + x] = scratch_[2 * x + 1];
    }
    return true;
}

bool Y4mReader::read_chroma(SourceImage& out, std::size_t& done) {
    out.chroma_width = header_.chroma_width();
    out.chroma_height = header_.chroma_height();
    const std::size_t plane = static_cast<std::size_t>(out.chroma_width) * static_cast<std::size_t>(out.chroma_height);
    out.u.resize(plane);  // no allocation once out has held a frame of this size
    out.v.resize(plane);
    if (plane > 0 && !(read_exact(out.u.data(), plane, done) && read_exact(out.v.data(), plane, done))) return false;
    for (std::size_t left = header_.chroma_bytes() - 2 * plane; left > 0;) {  // alpha
        const std::size_t chunk = std::min(left, scratch_.size());
        if (!read_exact(scratch_.data(), chunk, done)) return false;
        left -= chunk;
    }
    return true;
}

Y4mReader::Status Y4mReader::next(SourceImage& out) {
    if (sticky_ != Status::Frame) return sticky_;
    const Status marker = read_frame_marker();
    if (marker != Status::Frame) return marker;
    std::size_t done = 0;
    if (!read_luma(out, done) || !read_chroma(out, done)) return Status::Error;
    ++frames_read_;
    return Status::Frame;
}

}  // namespace rays::io
