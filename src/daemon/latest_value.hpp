// The newest value of something the frame loop produces (its status, the frame for a snapshot),
// handed to other threads without ever making the loop wait: the loop publishes with try_lock and
// skips a frame's update when a reader holds the lock; a reader copies under the lock.
#pragma once
#include <mutex>

namespace rays::daemon {

template <class T>
class LatestValue {
public:
    // Frame loop: copies `value` in unless a reader is busy; false when skipped.
    template <class Fill>
    bool try_publish(Fill&& fill) {
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (!lock.owns_lock()) return false;
        fill(value_);
        return true;
    }

    // Any other thread: runs `read` on the newest value under the lock.
    template <class Read>
    void read(Read&& reader) const {
        std::lock_guard lock(mutex_);
        reader(value_);
    }

private:
    mutable std::mutex mutex_;
    T value_{};
};

}  // namespace rays::daemon
