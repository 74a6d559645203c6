// SPDX-License-Identifier: Apache-2.0
#include "daemon/replay_source.hpp"

#include <sys/stat.h>

#include <thread>

namespace rays::daemon {
namespace {

constexpr double kDefaultFps = 25.0;  // pacing when the sequence does not say

bool is_rewindable(const std::string& path) {
    struct stat info {};
    return path != "-" && stat(path.c_str(), &info) == 0 && (S_ISREG(info.st_mode) || S_ISDIR(info.st_mode));
}

}  // namespace

std::unique_ptr<ReplaySource> ReplaySource::open(const CameraSettings& settings, const Clock& clock,
                                                 std::string& error) {
    if (settings.replay_path.empty()) {
        error = "camera.replay_path is not set";
        return nullptr;
    }
    io::OpenResult opened = io::open_frames(settings.replay_path);
    if (!opened.reader) {
        error = opened.error;
        return nullptr;
    }
    io::Crop crop{settings.crop_x, settings.crop_y, settings.crop_w, settings.crop_h};
    std::optional<io::FrameScaler> scaler =
        io::FrameScaler::make(opened.reader->width(), opened.reader->height(), opened.reader->chroma_width(),
                              opened.reader->chroma_height(), crop, error);
    if (!scaler) return nullptr;
    return std::unique_ptr<ReplaySource>(new ReplaySource(settings, clock, std::move(opened.reader), *scaler));
}

ReplaySource::ReplaySource(const CameraSettings& settings, const Clock& clock, std::unique_ptr<io::FrameReader> reader,
                           io::FrameScaler scaler)
    : settings_(settings),
      clock_(clock),
      reader_(std::move(reader)),
      scaler_(std::move(scaler)),
      fps_(reader_->fps() > 0 ? reader_->fps() : kDefaultFps),
      rewindable_(is_rewindable(settings.replay_path)) {}

bool ReplaySource::rewind() {
    io::OpenResult opened = io::open_frames(settings_.replay_path);
    if (!opened.reader || opened.reader->width() != reader_->width() || opened.reader->height() != reader_->height() ||
        opened.reader->chroma_width() != reader_->chroma_width() || opened.reader->chroma_height() != reader_->chroma_height()) {
        error_ = opened.reader ? settings_.replay_path + ": frame size changed" : opened.error;
        return false;
    }
    reader_ = std::move(opened.reader);
    since_rewind_ = 0;
    return true;
}

FrameSource::Result ReplaySource::next(CapturedFrame& out, std::chrono::milliseconds timeout) {
    if (settings_.replay_paced) {
        if (delivered_ == 0) first_due_ = clock_.now();
        TimePoint due = first_due_ + std::chrono::duration_cast<TimePoint::duration>(
                                         std::chrono::duration<double>(static_cast<double>(delivered_) / fps_));
        TimePoint now = clock_.now();
        if (due - now > timeout) {
            std::this_thread::sleep_for(timeout);
            return Result::Timeout;
        }
        if (due > now) std::this_thread::sleep_for(due - now);
    }
    io::FrameReader::Status status = reader_->next(decoded_);
    if (status == io::FrameReader::Status::End && settings_.replay_loop && rewindable_ && since_rewind_ > 0) {
        if (!rewind()) return Result::Error;
        status = reader_->next(decoded_);
    }
    if (status == io::FrameReader::Status::End) return Result::End;
    if (status == io::FrameReader::Status::Error) {
        error_ = reader_->error();
        return Result::Error;
    }
    scaler_.scale(decoded_, out.image, out.chroma);
    out.index = delivered_++;
    out.stamp = clock_.now();
    ++since_rewind_;
    return Result::Frame;
}

std::string ReplaySource::describe() const {
    std::string text = "replay " + settings_.replay_path + " " + std::to_string(reader_->width()) + "x" +
                       std::to_string(reader_->height());
    text += settings_.replay_paced ? " paced" : " unpaced";
    text += ", " + std::to_string(delivered_) + " frames delivered";
    if (!error_.empty()) text += ", error: " + error_;
    return text;
}

}  // namespace rays::daemon
