// SPDX-License-Identifier: Apache-2.0
#include "io/image_folder_reader.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>
#include <utility>

#include "io/pgm_decoder.hpp"

namespace rays::io {
namespace {

std::string lower_extension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool is_frame_file(const std::filesystem::directory_entry& entry) {
    std::error_code ec;
    if (!entry.is_regular_file(ec)) return false;
    const std::string ext = lower_extension(entry.path());
    return ext == ".pgm" || ext == ".png";
}

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

ImageFolderReader::ImageFolderReader(std::vector<std::filesystem::path> files) : files_(std::move(files)) {}

std::unique_ptr<ImageFolderReader> ImageFolderReader::open(const std::string& dir, std::string& error) {
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (is_frame_file(entry)) files.push_back(entry.path());
    if (ec) {
        error = dir + ": cannot list: " + ec.message();
        return nullptr;
    }
    if (files.empty()) {
        error = dir + ": no .pgm or .png files";
        return nullptr;
    }
    std::sort(files.begin(), files.end(),
              [](const auto& a, const auto& b) { return a.filename().string() < b.filename().string(); });
    std::unique_ptr<ImageFolderReader> reader(new ImageFolderReader(std::move(files)));
    if (!reader->decode(reader->files_.front(), reader->first_, error)) return nullptr;
    return reader;
}

bool ImageFolderReader::decode(const std::filesystem::path& file, SourceImage& out, std::string& error) {
    if (lower_extension(file) == ".pgm") return read_pgm(file.string(), out, error);
    return png_.decode(file.string(), out, error);
}

FrameReader::Status ImageFolderReader::next(SourceImage& out) {
    if (sticky_ != Status::Frame) return sticky_;
    if (next_index_ == files_.size()) return sticky_ = Status::End;
    const std::filesystem::path& file = files_[next_index_];
    if (next_index_ == 0) {
        out.width = first_.width;
        out.height = first_.height;
        out.grey = first_.grey;
    } else if (!decode(file, out, error_)) {
        return sticky_ = Status::Error;
    } else if (out.width != first_.width || out.height != first_.height) {
        error_ = file.string() + ": size " + size_text(out.width, out.height) + " differs from the first frame's " +
                 size_text(first_.width, first_.height);
        return sticky_ = Status::Error;
    }
    ++next_index_;
    return Status::Frame;
}

}  // namespace rays::io
