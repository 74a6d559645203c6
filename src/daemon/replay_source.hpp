// SPDX-License-Identifier: Apache-2.0
// Frames from a recording: a YUV4MPEG2 file, FIFO or standard input, or a folder of PGM/PNG
// images, cropped and area-scaled to 128×128, delivered at the sequence's frame rate or as fast as
// the loop takes them, optionally looping. A FIFO or stdin delivers frames as they arrive.
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "core/clock.hpp"
#include "daemon/daemon_config.hpp"
#include "daemon/frame_source.hpp"
#include "io/frame_scaler.hpp"
#include "io/frame_reader.hpp"

namespace rays::daemon {

class ReplaySource final : public FrameSource {
public:
    // Opens the sequence and checks the crop against its frame size; null with `error` on failure.
    static std::unique_ptr<ReplaySource> open(const CameraSettings& settings, const Clock& clock, std::string& error);

    Result next(CapturedFrame& out, std::chrono::milliseconds timeout) override;
    bool live() const override { return false; }
    std::string describe() const override;

    long delivered() const { return delivered_; }

private:
    ReplaySource(const CameraSettings& settings, const Clock& clock, std::unique_ptr<io::FrameReader> reader,
                 io::FrameScaler scaler);
    bool rewind();

    CameraSettings settings_;
    const Clock& clock_;
    std::unique_ptr<io::FrameReader> reader_;
    io::FrameScaler scaler_;
    io::SourceImage decoded_;
    double fps_;
    bool rewindable_;
    TimePoint first_due_{};
    long delivered_ = 0;
    long since_rewind_ = 0;
    std::string error_;
};

}  // namespace rays::daemon
