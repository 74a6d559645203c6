// SPDX-License-Identifier: Apache-2.0
// The driver's capture buffers (V4L2 mmap streaming I/O), mapped into this process.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "capture/video_device.hpp"

namespace rays::capture {

class MappedBuffers {
public:
    struct Mapping {
        void* address = nullptr;
        std::size_t length = 0;
    };

    // REQBUFS for `count` buffers (the driver may grant others; fewer than 2 fails), then QUERYBUF and
    // mmap each and QBUF them all. On failure returns false with error; what was mapped stays mapped
    // until release().
    bool allocate(VideoDevice& device, int fd, int count, DeviceError& error);
    // Unmaps every buffer. The driver frees them when the fd is closed.
    void release(VideoDevice& device);

    int count() const { return static_cast<int>(mappings_.size()); }
    const std::uint8_t* data(std::uint32_t index) const { return static_cast<const std::uint8_t*>(mappings_[index].address); }
    std::size_t length(std::uint32_t index) const { return mappings_[index].length; }

private:
    std::vector<Mapping> mappings_;
};

}  // namespace rays::capture
