// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the input as a YUV4MPEG2 stream into Y4mReader (up to 64 frames) and its first
// line into parse_y4m_header. Frames have the header's size; End and Error are final.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "io/y4m_header.hpp"
#include "io/y4m_reader.hpp"

namespace {

using rays::fuzz::expect;
using namespace rays::io;

bool side_in_range(int side) { return side >= 1 && side <= kMaxY4mSide; }

// The header parser alone; true when it accepts the first line.
bool check_header(std::string_view input) {
    Y4mHeader header;
    std::string error;
    const bool ok = parse_y4m_header(input.substr(0, input.find('\n')), header, error);
    expect(ok || !error.empty(), "a refused header has a reason");
    if (!ok) return false;
    expect(side_in_range(header.width) && side_in_range(header.height), "header sides are in range");
    expect(header.fps_num >= 0 && header.fps_den >= 0 && header.fps() >= 0, "frame rate is not negative");
    expect(header.frame_bytes() >= header.luma_bytes(), "a frame holds its luma plane");
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static rays::fuzz::MemoryFile file;
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const bool header_ok = check_header(input);
    file.write(data, size);
    std::string error;
    auto reader = Y4mReader::open(file.path(), error);
    if (!reader) {
        expect(!error.empty(), "a failed open has a reason");
        return 0;
    }
    expect(header_ok, "the reader accepts only headers the parser accepts");
    expect(side_in_range(reader->width()) && side_in_range(reader->height()), "reader sides are in range");
    SourceImage image;
    FrameReader::Status status = FrameReader::Status::Frame;
    for (int frame = 0; frame < 64; ++frame) {
        status = reader->next(image);
        if (status != FrameReader::Status::Frame) break;
        expect(image.width == reader->width() && image.height == reader->height(), "a frame has the header's size");
        expect(image.grey.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height),
               "a frame's luma plane is width x height");
        expect(reader->frames_read() == frame + 1, "frames are counted");
    }
    if (status == FrameReader::Status::Error) expect(!reader->error().empty(), "an error has a message");
    if (status != FrameReader::Status::Frame) expect(reader->next(image) == status, "End and Error are final");
    return 0;
}
