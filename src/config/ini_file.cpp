// SPDX-License-Identifier: Apache-2.0
#include "config/ini_file.hpp"

#include <ini.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace rays::config {
namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// The file's lines without their '\n'; nullopt and `error` set when it cannot be read.
std::optional<std::vector<std::string>> read_lines(const std::string& path, std::string& error) {
    File file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        error = std::string("cannot open: ") + std::strerror(errno);
        return std::nullopt;
    }
    std::vector<std::string> lines;
    std::string line;
    int c = 0;
    while ((c = std::fgetc(file.get())) != EOF) {
        if (c == '\n') {
            lines.push_back(std::move(line));
            line.clear();
        } else {
            line.push_back(static_cast<char>(c));
        }
    }
    if (std::ferror(file.get())) {
        error = std::string("cannot read: ") + std::strerror(errno);
        return std::nullopt;
    }
    if (!line.empty()) lines.push_back(std::move(line));
    constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
    if (!lines.empty() && lines.front().starts_with(byte_order_mark)) lines.front().erase(0, byte_order_mark.size());
    return lines;
}

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && (is_blank(text.front()) || text.front() == '\r')) text.remove_prefix(1);
    while (!text.empty() && (is_blank(text.back()) || text.back() == '\r')) text.remove_suffix(1);
    return text;
}

// The name libinih gives a "[name]" line: everything between '[' and the first ']', untrimmed.
std::optional<std::string_view> section_header(std::string_view line) {
    line = trimmed(line);
    if (line.empty() || line.front() != '[') return std::nullopt;
    std::size_t close = line.find(']');
    if (close == std::string_view::npos) return std::nullopt;  // libinih reports the syntax error
    return line.substr(1, close - 1);
}

struct ParseState {
    ParseState(std::vector<std::string> file_lines, const IniVisitor& ini_visitor)
        : lines(std::move(file_lines)), visitor(ini_visitor) {}

    std::vector<std::string> lines;
    const IniVisitor& visitor;
    std::size_t next = 0;  // index of the next line to hand to libinih
    int line = 0;          // 1-based number of the line libinih is parsing
    std::string last_key;  // key of the last entry since the last header (libinih's "prev_name")
    std::optional<std::pair<int, std::string>> error;

    std::string_view current() const { return lines[next - 1]; }
    void fail(std::string message) { error.emplace(line, std::move(message)); }
};

// ini_reader: gives libinih one physical line per call, so its count and ours agree.
char* next_line(char* buffer, int size, void* stream) {
    ParseState& state = *static_cast<ParseState*>(stream);
    if (state.error || state.next == state.lines.size()) return nullptr;  // returning null ends parsing
    const std::string& text = state.lines[state.next++];
    state.line = static_cast<int>(state.next);
    if (text.size() + 2 > static_cast<std::size_t>(size)) {  // room for '\n' and '\0'
        state.fail("line is longer than " + std::to_string(size - 2) + " characters");
        return nullptr;
    }
    if (auto name = section_header(text)) {
        state.last_key.clear();
        if (auto message = state.visitor.section(*name)) {
            state.fail(std::move(*message));
            return nullptr;
        }
    }
    std::memcpy(buffer, text.data(), text.size());
    buffer[text.size()] = '\n';
    buffer[text.size() + 1] = '\0';
    return buffer;
}

// ini_handler: always returns 1, so libinih's own result counts syntax errors only.
int on_entry(void* user, const char* section, const char* key, const char* value) {
    ParseState& state = *static_cast<ParseState*>(user);
    if (state.error) return 1;
    // libinih appends an indented line to the previous key's value (multi-line values).
    if (!state.last_key.empty() && is_blank(state.current().front())) {
        state.fail("indented line would continue the value of " + state.last_key +
                   "; multi-line values are not supported, remove the indentation");
        return 1;
    }
    state.last_key = key;
    if (auto message = state.visitor.entry(IniEntry{section, key, value, state.line}))
        state.fail(std::move(*message));
    return 1;
}

}  // namespace

std::optional<ConfigError> read_ini(const std::string& path, const IniVisitor& visitor) {
    std::string read_error;
    auto lines = read_lines(path, read_error);
    if (!lines) return ConfigError{path, 0, read_error};
    ParseState state(std::move(*lines), visitor);
    int syntax_line = ini_parse_stream(next_line, &state, on_entry, &state);
    if (syntax_line > 0 && (!state.error || syntax_line < state.error->first)) {
        std::string text(trimmed(state.lines[static_cast<std::size_t>(syntax_line - 1)]));
        return ConfigError{path, syntax_line, "expected [section], key = value or a comment, not '" + text + "'"};
    }
    if (state.error) return ConfigError{path, state.error->first, state.error->second};
    return std::nullopt;
}

}  // namespace rays::config
