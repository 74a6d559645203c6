// SPDX-License-Identifier: Apache-2.0
#include "soak_options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <utility>

namespace rays::soak {
namespace {

template <class T>
std::optional<T> number(std::string_view text) {
    T value{};
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
    return value;
}

std::optional<double> positive(std::string_view text) {
    std::optional<double> v = number<double>(text);
    if (!v || !std::isfinite(*v) || *v <= 0) return std::nullopt;
    return v;
}

// "A<separator>B" with 0 <= A <= B (a range of seeds, a window of seconds).
template <class T>
std::optional<std::pair<T, T>> ordered_pair(std::string_view text, char separator) {
    const std::size_t at = text.find(separator);
    if (at == std::string_view::npos) return std::nullopt;
    std::optional<T> first = number<T>(text.substr(0, at)), last = number<T>(text.substr(at + 1));
    if (!first || !last || *first < 0 || *last < *first) return std::nullopt;
    return std::pair{*first, *last};
}

}  // namespace

std::optional<std::string> parse_options(int argc, const char* const* argv, SoakOptions& out) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--json") {
            out.json = true;
            continue;
        }
        if (arg == "--lockstep") {
            out.lockstep = true;
            continue;
        }
        if (arg == "--help" || arg == "-h") {
            out.help = true;
            continue;
        }
        static constexpr std::string_view kValued[] = {"--frames", "--scenario", "--seed", "--seeds", "--config", "--law",
                                                       "--method", "--gain", "--sweep-gain", "--compare", "--budget-ms", "--plot", "--trace", "--overlay", "--overlay-window"};
        if (std::find(std::begin(kValued), std::end(kValued), arg) == std::end(kValued))
            return "unknown argument '" + std::string(arg) + "'";
        if (i + 1 == argc) return std::string(arg) + " needs a value";
        const std::string_view value = argv[++i];
        const std::string bad = std::string(arg) + ": bad value '" + std::string(value) + "'";
        if (arg == "--frames") {
            std::optional<long> n = number<long>(value);
            if (!n || *n <= 0) return bad + " (a positive integer)";
            out.frames = *n;
        } else if (arg == "--seed") {
            std::optional<int> n = number<int>(value);
            if (!n || *n < 0) return bad + " (an integer ≥ 0)";
            out.seed = *n;
        } else if (arg == "--seeds") {
            out.seeds = ordered_pair<int>(value, '-');
            if (!out.seeds) return bad + " (A-B with 0 <= A <= B)";
        } else if (arg == "--scenario") {
            out.scenario = std::string(value);
        } else if (arg == "--config") {
            out.config_path = value;
        } else if (arg == "--plot") {
            out.plot_path = value;
        } else if (arg == "--trace") {
            out.trace_path = value;
        } else if (arg == "--overlay") {
            out.overlay_dir = value;
        } else if (arg == "--overlay-window") {
            const std::optional<std::pair<double, double>> window = ordered_pair<double>(value, ',');
            if (!window) return bad + " (FROM_S,TO_S with 0 <= FROM_S <= TO_S)";
            out.overlay_from_s = window->first;
            out.overlay_to_s = window->second;
        } else if (arg == "--law") {
            if (value != "predictive" && value != "proportional") return bad + " (predictive or proportional)";
            out.law = std::string(value);
        } else if (arg == "--method") {
            if (value != "rays" && value != "snake") return bad + " (rays or snake)";
            out.method = std::string(value);
        } else if (arg == "--gain" || arg == "--budget-ms") {
            std::optional<double> v = positive(value);
            if (!v) return bad + " (a positive number)";
            (arg == "--gain" ? out.gain : out.budget_ms) = *v;
        } else {  // --sweep-gain, --compare
            std::vector<double>& gains = arg == "--compare" ? out.compare_gains : out.sweep_gains;
            std::string_view rest = value;
            while (!rest.empty()) {
                std::size_t comma = rest.find(',');
                std::optional<double> v = positive(rest.substr(0, comma));
                if (!v) return bad + " (positive numbers separated by commas)";
                gains.push_back(*v);
                rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
            }
        }
    }
    const int modes = (out.gain ? 1 : 0) + (out.sweep_gains.empty() ? 0 : 1) + (out.compare_gains.empty() ? 0 : 1);
    if (modes > 1) return "--gain, --sweep-gain and --compare exclude each other";
    if (out.lockstep && out.budget_ms) return "--lockstep has no budget: no --budget-ms";
    if (out.seeds && out.seed) return "--seed and --seeds exclude each other";
    if (out.seeds && (!out.sweep_gains.empty() || !out.compare_gains.empty()))
        return "--seeds runs one gain: no --sweep-gain or --compare";
    if (out.seeds && (!out.plot_path.empty() || !out.trace_path.empty() || !out.overlay_dir.empty()))
        return "--plot, --trace and --overlay are for one run: not with --seeds";
    if (!out.compare_gains.empty() && (out.law || out.method))
        return "--compare runs both laws and both methods itself: no --law or --method";
    return std::nullopt;
}

}  // namespace rays::soak
