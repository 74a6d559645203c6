// SPDX-License-Identifier: Apache-2.0
// The newest value one thread produces for another, handed over without the real-time side ever
// waiting: it uses the try_ forms, which skip (and say so) when the other thread holds the lock for
// its short copy; the other side uses the plain forms. Examples: the frame loop publishes its status
// for the socket thread; a driver's I/O thread takes the newest command and publishes the newest state.
#pragma once
#include <mutex>

namespace rays {

template <class T>
class LatestValue {
public:
    // Real-time side: runs `fill` on the value unless the other side is busy; false when skipped.
    template <class Fill>
    bool try_publish(Fill&& fill) {
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (!lock.owns_lock()) return false;
        fill(value_);
        return true;
    }

    // Real-time side: runs `reader` on the value unless the other side is busy; false when skipped.
    template <class Read>
    bool try_read(Read&& reader) const {
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (!lock.owns_lock()) return false;
        reader(value_);
        return true;
    }

    // Other side: runs `fill` on the value under the lock.
    template <class Fill>
    void publish(Fill&& fill) {
        std::lock_guard lock(mutex_);
        fill(value_);
    }

    // Other side: runs `reader` on the value under the lock.
    template <class Read>
    void read(Read&& reader) const {
        std::lock_guard lock(mutex_);
        reader(value_);
    }

private:
    mutable std::mutex mutex_;
    T value_{};
};

}  // namespace rays
