// SPDX-License-Identifier: Apache-2.0
// What the fuzz targets share: an invariant check that crashes the fuzzer, and an in-memory file
// (memfd) rewritten per input that product code opens by path.
#pragma once
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace rays::fuzz {

inline void expect(bool holds, const char* invariant) {
    if (holds) return;
    std::fprintf(stderr, "invariant broken: %s\n", invariant);
    std::abort();
}

class MemoryFile {
public:
    MemoryFile() : fd_(memfd_create("rays-fuzz", 0)), path_("/proc/self/fd/" + std::to_string(fd_)) {
        expect(fd_ >= 0, "memfd_create succeeds");
    }
    ~MemoryFile() { close(fd_); }
    MemoryFile(const MemoryFile&) = delete;
    MemoryFile& operator=(const MemoryFile&) = delete;

    // Replaces the contents with `size` bytes of `data`.
    void write(const void* data, std::size_t size) {
        expect(ftruncate(fd_, 0) == 0, "memfd truncates");
        expect(pwrite(fd_, data, size, 0) == static_cast<ssize_t>(size), "memfd takes the input");
    }
    const std::string& path() const { return path_; }

private:
    int fd_;
    std::string path_;
};

}  // namespace rays::fuzz
