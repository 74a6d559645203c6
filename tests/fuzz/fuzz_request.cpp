// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: request lines into RequestHandler::handle. The input is one line to a fresh
// handler, then its '\n'-separated lines to another one, so state is reached (watch, set then get).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

#include "core/clock.hpp"
#include "daemon/request_handler.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace rays::daemon;
using nlohmann::json;
using rays::fuzz::expect;

struct Daemon {
    rays::SteadyClock clock;
    DaemonConfig config;
    LoopChannels channels{2};
    RequestHandler handler{config, channels, DaemonFacts{"mock"}, [] { return std::string("camera ok"); }, clock};
    ClientSession session;

    void ask(std::string_view line) {
        json reply = handler.handle(line, session);
        expect(reply.is_object(), "a reply is a JSON object");
        auto cls = reply.find("class");
        expect(cls != reply.end() && cls->is_string(), "a reply has a string \"class\"");
        expect(!reply.dump(-1, ' ', false, json::error_handler_t::replace).empty(), "a reply serialises");
        LoopCommand command;
        while (channels.commands.pop(command)) {}  // the frame loop's part: the queue never stays full
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    std::make_unique<Daemon>()->ask(input);
    auto daemon = std::make_unique<Daemon>();
    for (std::size_t start = 0; start <= input.size();) {
        const std::size_t end = std::min(input.find('\n', start), input.size());
        daemon->ask(input.substr(start, end - start));
        start = end + 1;
    }
    return 0;
}
