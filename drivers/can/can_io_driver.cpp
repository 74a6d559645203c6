// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/can_io_driver.hpp"

#include <algorithm>
#include <cstdio>

namespace rays::can {
namespace {

TimePoint::duration seconds(double s) {
    return std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(s));
}

}  // namespace

CanIoDriver::CanIoDriver(std::unique_ptr<CanTransport> transport, const Clock& clock, const CanIoTiming& timing)
    : transport_(std::move(transport)), clock_(clock), timing_(timing) {}

void CanIoDriver::stop_thread() {
    goal_ = Goal::Off;
    running_ = false;
    transport_->wake();
    if (thread_.joinable()) thread_.join();
    transport_->close();
    report_.publish([](IoReport& report) {  // stopped: nothing is enabled any more
        report.enabled = false;
        for (ptu::AxisState& axis : report.state.axes) axis.enabled = false;
    });
}

ptu::DriverStatus CanIoDriver::configure() {
    stop_thread();
    std::string error;
    if (!transport_->open(error)) {
        char text[120];
        std::snprintf(text, sizeof text, "%s: %s", name(), error.c_str());
        return ptu::DriverStatus::failure(text);
    }
    report_.publish([](IoReport& report) { report = IoReport{}; });
    link_down_ = false;
    open_backoff_s_ = 0.5;
    goal_ = Goal::Configured;
    running_ = true;
    thread_ = std::thread([this] { run(); });
    ptu::DriverStatus failure;
    if (wait_for(&IoReport::configured, failure)) return ptu::DriverStatus::success();
    stop_thread();
    return failure;
}

ptu::DriverStatus CanIoDriver::activate() {
    if (!running_) return ptu::DriverStatus::failure("activate before configure");
    goal_ = Goal::Enabled;
    transport_->wake();
    ptu::DriverStatus failure;
    if (wait_for(&IoReport::enabled, failure)) return ptu::DriverStatus::success();
    goal_ = Goal::Configured;
    return failure;
}

void CanIoDriver::deactivate() { stop_thread(); }

bool CanIoDriver::wait_for(bool IoReport::*flag, ptu::DriverStatus& failure) {
    const TimePoint deadline = MonoClock::now() + seconds(timing_.lifecycle_timeout_s);
    ptu::DriverStatus waiting;
    for (;;) {
        bool done = false;
        report_.read([&](const IoReport& report) {
            done = report.*flag;
            failure = report.status;
            waiting = report.waiting;
        });
        if (done) return true;
        // configure() checks that the drives answer: their first failure is the answer.
        if (!failure.ok && flag == &IoReport::configured) return false;
        if (MonoClock::now() >= deadline) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (failure.ok && !waiting.ok) failure = waiting;
    if (failure.ok) {
        char text[120];
        std::snprintf(text, sizeof text, "%s: the drives did not become %s within %.1f s", name(),
                      flag == &IoReport::configured ? "configured" : "enabled", timing_.lifecycle_timeout_s);
        failure = ptu::DriverStatus::failure(text);
    }
    return false;
}

ptu::DriverStatus CanIoDriver::write(const ptu::PtuCommand& command, TimePoint now) {
    (void)now;
    const std::uint64_t sequence = ++written_;
    command_.try_publish([&](CommandMail& mail) { mail = CommandMail{command, sequence}; });
    transport_->wake();
    report_.try_read([&](const IoReport& report) { last_status_ = report.status; });
    if (!running_) return ptu::DriverStatus::failure("write while not configured");
    return last_status_;
}

ptu::DriverStatus CanIoDriver::read(ptu::PtuState& state, TimePoint now) {
    (void)now;
    report_.try_read([&](const IoReport& report) {
        state = report.state;
        last_status_ = report.status;
    });
    return last_status_;
}

bool CanIoDriver::send(const can_frame& frame) {
    if (link_down_) return false;
    const CanIo result = transport_->send(frame);
    if (result == CanIo::Down) {
        link_down_ = true;
        char text[120];
        std::snprintf(text, sizeof text, "%s: %s; reopening", name(), transport_->last_error());
        link_status_ = ptu::DriverStatus::failure(text);
    }
    return result == CanIo::Ok;
}

bool CanIoDriver::reopen(TimePoint now) {
    if (now < next_open_) return false;
    transport_->close();
    std::string error;
    if (!transport_->open(error)) {
        next_open_ = now + seconds(open_backoff_s_);
        open_backoff_s_ = std::min(open_backoff_s_ * 2.0, 8.0);
        return false;
    }
    link_down_ = false;
    open_backoff_s_ = 0.5;
    io_start(now);
    return true;
}

void CanIoDriver::publish(TimePoint now) {
    IoReport report = io_report(now);
    if (link_down_) {
        report.status = link_status_;
        report.enabled = false;
        for (ptu::AxisState& axis : report.state.axes) {
            axis.fault = true;
            axis.enabled = false;
        }
    }
    report_.publish([&](IoReport& out) { out = report; });
}

void CanIoDriver::run() {
    const auto cycle = seconds(timing_.cycle_s);
    const auto stale_after = seconds(timing_.command_timeout_s);
    TimePoint now = clock_.now();
    io_start(now);
    TimePoint next_cycle = now;
    std::uint64_t seen = 0;
    TimePoint last_fresh = now;
    while (running_) {
        can_frame frame{};
        const auto wait = std::chrono::duration_cast<std::chrono::microseconds>(next_cycle - clock_.now());
        const CanIo result = link_down_ ? CanIo::Timeout
                                        : transport_->receive(frame, std::max(wait, std::chrono::microseconds(0)));
        now = clock_.now();
        if (result == CanIo::Ok) {
            const CanBusEvent event = classify_error_frame(frame);
            if (event == CanBusEvent::None) io_frame(frame, now);
            else io_bus_event(event, now);
            if (now < next_cycle) continue;
        } else if (result == CanIo::Down) {
            link_down_ = true;
            char text[120];
            std::snprintf(text, sizeof text, "%s: %s; reopening", name(), transport_->last_error());
            link_status_ = ptu::DriverStatus::failure(text);
        }
        if (link_down_ && !reopen(now)) {
            if (result != CanIo::Timeout || wait.count() <= 0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
            publish(now);
            next_cycle = now + cycle;
            continue;
        }
        CommandMail mail;
        command_.read([&](const CommandMail& newest) { mail = newest; });
        const bool fresh = mail.sequence != seen;
        if (fresh) {
            seen = mail.sequence;
            last_fresh = now;
        }
        const bool usable = goal_ == Goal::Enabled && mail.sequence != 0 && now - last_fresh < stale_after;
        io_cycle(usable ? mail.command : ptu::PtuCommand::stop(), fresh && usable, now);
        publish(now);
        if (now >= next_cycle) next_cycle = now + cycle;
    }
    io_stop(clock_.now());
}

}  // namespace rays::can
