// SPDX-License-Identifier: Apache-2.0
#include "io/frame_reader.hpp"

#include <filesystem>
#include <system_error>

#include "io/image_folder_reader.hpp"
#include "io/y4m_reader.hpp"

namespace rays::io {

FrameReader::~FrameReader() = default;

OpenResult open_frames(const std::string& path) {
    OpenResult result;
    if (path == "-") {
        result.reader = Y4mReader::open_stdin(result.error);
        return result;
    }
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) {
        result.error = path + ": no such file or directory";
        return result;
    }
    if (std::filesystem::is_directory(status))
        result.reader = ImageFolderReader::open(path, result.error);
    else
        result.reader = Y4mReader::open(path, result.error);
    return result;
}

}  // namespace rays::io
