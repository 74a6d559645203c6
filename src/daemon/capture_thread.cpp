// SPDX-License-Identifier: Apache-2.0
#include "daemon/capture_thread.hpp"

#include "daemon/log.hpp"

namespace rays::daemon {
namespace {

constexpr std::chrono::milliseconds kPollInterval{100};
constexpr long kStatusEvery = 25;  // frames between status refreshes

}  // namespace

CaptureThread::CaptureThread(FrameSource& source, LoopChannels& channels, const Clock& clock)
    : source_(source), channels_(channels), clock_(clock), status_(source.describe()) {}

CaptureThread::~CaptureThread() { stop(std::chrono::milliseconds(1000)); }

void CaptureThread::start() { thread_ = std::thread([this] { run(); }); }

void CaptureThread::stop(std::chrono::milliseconds grace) {
    stop_.store(true);
    if (!thread_.joinable()) return;
    for (auto waited = std::chrono::milliseconds(0); waited < grace && !finished_.load();
         waited += std::chrono::milliseconds(10))
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (finished_.load()) thread_.join();
    else thread_.detach();  // blocked in the source's read; the process exit ends it
}

std::string CaptureThread::status() const {
    std::lock_guard lock(status_mutex_);
    return status_;
}

void CaptureThread::set_status(std::string text) {
    std::lock_guard lock(status_mutex_);
    status_ = std::move(text);
}

bool CaptureThread::queue(const CapturedFrame& frame) {
    while (!stop_.load()) {
        switch (channels_.frames.push(frame, !source_.live(), kPollInterval)) {
        case FrameQueue::Push::Queued:
        case FrameQueue::Push::Replaced: return true;
        case FrameQueue::Push::TimedOut: continue;
        case FrameQueue::Push::Closed: return false;
        }
    }
    return false;
}

void CaptureThread::run() {
    CapturedFrame frame;
    bool ended = false;
    while (!stop_.load() && !ended) {
        switch (source_.next(frame, kPollInterval)) {
        case FrameSource::Result::Frame:
            frame.arrived = clock_.now();
            if (!channels_.camera_connected.exchange(true)) set_status(source_.describe());
            if (!queue(frame)) ended = true;
            if (delivered_.fetch_add(1) % kStatusEvery == 0) set_status(source_.describe());
            break;
        case FrameSource::Result::Timeout: break;
        case FrameSource::Result::Disconnected:
            channels_.camera_connected.store(false);
            channels_.frames.wake();
            log(Priority::Warning, "camera disconnected: %s", source_.describe().c_str());
            set_status(source_.describe());
            break;
        case FrameSource::Result::End:
            log(Priority::Notice, "frame source ended: %s", source_.describe().c_str());
            set_status("ended: " + source_.describe());
            ended = true;
            break;
        case FrameSource::Result::Error:
            channels_.camera_connected.store(false);
            channels_.frames.wake();
            log(Priority::Err, "frame source failed: %s", source_.describe().c_str());
            set_status("failed: " + source_.describe());
            ended = true;
            break;
        }
    }
    finished_.store(true);
}

}  // namespace rays::daemon
