// SPDX-License-Identifier: Apache-2.0
// A sequence of recorded frames (YUV4MPEG2 stream or a folder of images), read one at a time.
#pragma once
#include <memory>
#include <string>

#include "io/source_image.hpp"

namespace rays::io {

class FrameReader {
public:
    virtual ~FrameReader();

    enum class Status { Frame, End, Error };

    // Decodes the next frame into out, reusing its buffer: no allocation after the first frame.
    // After End or Error every further call returns the same status.
    virtual Status next(SourceImage& out) = 0;
    // One line describing the last Error (empty otherwise).
    virtual const std::string& error() const = 0;
    virtual int width() const = 0;
    virtual int height() const = 0;
    // Frames per second, 0 if unknown.
    virtual double fps() const = 0;
    // The size of the frames' Cb and Cr planes; 0 for a mono source (then SourceImage has none).
    virtual int chroma_width() const { return 0; }
    virtual int chroma_height() const { return 0; }
};

struct OpenResult {
    std::unique_ptr<FrameReader> reader;  // null on failure
    std::string error;
};

// A directory is read as an image folder; anything else (file, FIFO, "-" for stdin) as YUV4MPEG2.
OpenResult open_frames(const std::string& path);

}  // namespace rays::io
