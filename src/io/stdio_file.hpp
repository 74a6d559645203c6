// SPDX-License-Identifier: Apache-2.0
// Owning handle for a C stdio stream: closes it when the owner goes away.
#pragma once
#include <cstdio>
#include <memory>

namespace rays::io {

struct StdioCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using StdioFile = std::unique_ptr<std::FILE, StdioCloser>;

}  // namespace rays::io
