// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <atomic>
#include <chrono>
#include <future>
#include <string>
#include <thread>
#include <vector>

#include "io/frame_reader.hpp"
#include "support/temp_dir.hpp"

using rays::io::FrameReader;
using rays::io::open_frames;
using rays::io::SourceImage;
using Status = FrameReader::Status;

namespace {

constexpr int kW = 6;
constexpr int kH = 4;
constexpr int kFrames = 3;

std::string frame_bytes(int f) {
    std::string luma(kW * kH, static_cast<char>(10 + 40 * f));
    return "FRAME\n" + luma + std::string(2 * 3 * 2, '\x80');  // 4:2:0 chroma of 6x4
}

bool write_all(int fd, const std::string& data) {
    std::size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// Writes the header, then each frame only once the reader has delivered the previous one: a reader that
// waited for more data than one frame would stall here (and the writer gives up after a timeout).
struct Pacing {
    std::vector<std::promise<void>> delivered{kFrames};  // set by the reader
    std::vector<std::future<void>> awaited;               // waited on by the writer
    std::atomic<bool> stalled{false};

    Pacing() {
        std::signal(SIGPIPE, SIG_IGN);  // a failing reader must not kill the test through the writer
        for (auto& p : delivered) awaited.push_back(p.get_future());
    }
};

void paced_writer(int fd, Pacing& pacing) {
    write_all(fd, "YUV4MPEG2 W6 H4 F25:1 Ip A1:1 C420jpeg XYSCSS=420JPEG\n");
    for (int f = 0; f < kFrames; ++f) {
        write_all(fd, frame_bytes(f));
        if (pacing.awaited[static_cast<std::size_t>(f)].wait_for(std::chrono::seconds(10)) != std::future_status::ready)
            pacing.stalled = true;
    }
    ::close(fd);
}

// Uses CHECK only, so the writer thread is always joined.
void read_paced(const std::string& path, Pacing& pacing) {
    auto opened = open_frames(path);
    CHECK(opened.error.empty());
    if (!opened.reader) return;
    CHECK(opened.reader->width() == kW);
    SourceImage img;
    for (int f = 0; f < kFrames; ++f) {
        const Status status = opened.reader->next(img);
        CHECK(status == Status::Frame);
        if (status != Status::Frame) return;
        CHECK(img.grey == std::vector<std::uint8_t>(kW * kH, static_cast<std::uint8_t>(10 + 40 * f)));
        pacing.delivered[static_cast<std::size_t>(f)].set_value();
    }
    CHECK(opened.reader->next(img) == Status::End);
}

}  // namespace

TEST_CASE("frames from a pipe are delivered as they arrive") {
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
    Pacing pacing;
    std::thread writer(paced_writer, fds[1], std::ref(pacing));
    read_paced("/dev/fd/" + std::to_string(fds[0]), pacing);
    ::close(fds[0]);
    writer.join();
    CHECK_FALSE(pacing.stalled);
}

TEST_CASE("frames from a named FIFO are delivered as they arrive") {
    rays::test::TempDir dir;
    const std::string fifo = dir.file("camera.fifo");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    Pacing pacing;
    std::thread writer([&] {
        const int fd = ::open(fifo.c_str(), O_WRONLY);  // blocks until the reader opens
        if (fd >= 0) paced_writer(fd, pacing);
    });
    read_paced(fifo, pacing);
    writer.join();
    CHECK_FALSE(pacing.stalled);
}
