// SPDX-License-Identifier: Apache-2.0
#include "capture/mapped_buffers.hpp"

#include <linux/videodev2.h>
#include <sys/mman.h>

namespace rays::capture {

bool MappedBuffers::allocate(VideoDevice& device, int fd, int count, DeviceError& error) {
    v4l2_requestbuffers request{};
    request.count = static_cast<std::uint32_t>(count);
    request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    request.memory = V4L2_MEMORY_MMAP;
    if (ioctl_retrying(device, fd, VIDIOC_REQBUFS, &request) == -1) {
        error = call_failed("VIDIOC_REQBUFS");
        return false;
    }
    if (request.count < 2) {
        error = DeviceError{0, "the driver granted " + std::to_string(request.count) + " buffers, 2 are needed"};
        return false;
    }
    mappings_.reserve(request.count);
    for (std::uint32_t index = 0; index < request.count; ++index) {
        v4l2_buffer buffer{};
        buffer.index = index;
        buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        buffer.memory = V4L2_MEMORY_MMAP;
        if (ioctl_retrying(device, fd, VIDIOC_QUERYBUF, &buffer) == -1) {
            error = call_failed("VIDIOC_QUERYBUF");
            return false;
        }
        void* address = device.mmap(buffer.length, PROT_READ | PROT_WRITE, MAP_SHARED, fd, buffer.m.offset);
        if (address == MAP_FAILED) {
            error = call_failed("mmap");
            return false;
        }
        mappings_.push_back(Mapping{address, buffer.length});
        if (ioctl_retrying(device, fd, VIDIOC_QBUF, &buffer) == -1) {
            error = call_failed("VIDIOC_QBUF");
            return false;
        }
    }
    return true;
}

void MappedBuffers::release(VideoDevice& device) {
    for (const Mapping& mapping : mappings_) device.munmap(mapping.address, mapping.length);
    mappings_.clear();
}

}  // namespace rays::capture
