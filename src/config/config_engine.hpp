// SPDX-License-Identifier: Apache-2.0
// What a parameter table gives its settings struct: loading an INI file, get and set by name with
// the same validation, the JSON echo of every setting, the documented sample file and the listing.
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/config_error.hpp"
#include "config/config_messages.hpp"
#include "config/ini_file.hpp"
#include "config/param_table.hpp"
#include "config/param_text.hpp"

namespace rays::config {

// Reads `path` over the defaults Root{}: keys absent keep their defaults. Checks every key, then
// the cross-field rules, blaming the line of the last key set among those a rule relates.
// `out` changes only when the whole file is valid.
template <class Root>
std::optional<ConfigError> load_ini(const std::string& path, const ParamTable<Root>& table, Root& out) {
    Root candidate{};
    std::map<std::string, int, std::less<>> line_of_key;
    IniVisitor visitor;
    visitor.section = [&](std::string_view name) -> std::optional<std::string> {
        std::vector<std::string_view> sections = table.sections();
        for (std::string_view known : sections)
            if (known == name) return std::nullopt;
        return unknown_section_message(name, sections);
    };
    visitor.entry = [&](const IniEntry& entry) -> std::optional<std::string> {
        if (entry.section.empty()) return key_outside_section_message(entry.key, table.names());
        std::string name = std::string(entry.section) + "." + std::string(entry.key);
        const Param<Root>* param = table.find(name);
        if (param == nullptr) return unknown_parameter_message(name, table.names());
        if (auto first = line_of_key.find(name); first != line_of_key.end())
            return name + " is set twice (first on line " + std::to_string(first->second) + ")";
        ParamValue value;
        if (auto error = parse_value(param->info, entry.value, value)) return error;
        param->write(candidate, value);
        line_of_key.emplace(name, entry.line);
        return std::nullopt;
    };
    if (auto error = read_ini(path, visitor)) return error;
    if (auto violation = table.check_rules(candidate)) {
        int line = 0;
        for (const std::string& key : violation->rule->keys)
            if (auto set = line_of_key.find(key); set != line_of_key.end() && set->second > line) line = set->second;
        return ConfigError{path, line, violation->message};
    }
    out = candidate;
    return std::nullopt;
}

// Validated exactly as in a file, cross-field rules included; `root` changes only on success.
// Capacities size buffers at start, so they are refused unless `allow_capacity`.
template <class Root>
std::optional<std::string> set_param(const ParamTable<Root>& table, Root& root, std::string_view name,
                                     std::string_view text, bool allow_capacity) {
    const Param<Root>* param = table.find(name);
    if (param == nullptr) return unknown_parameter_message(name, table.names());
    if (param->info.kind == ParamKind::Capacity && !allow_capacity) return capacity_is_fixed_message(name);
    ParamValue value;
    if (auto error = parse_value(param->info, text, value)) return error;
    Root candidate = root;
    param->write(candidate, value);
    if (auto violation = table.check_rules(candidate)) return violation->message;
    root = candidate;
    return std::nullopt;
}

// The value as text that set_param and the INI file accept.
template <class Root>
std::optional<std::string> get_param(const ParamTable<Root>& table, const Root& root, std::string_view name,
                                     std::string& value_out) {
    const Param<Root>* param = table.find(name);
    if (param == nullptr) return unknown_parameter_message(name, table.names());
    value_out = format_value(param->read(root));
    return std::nullopt;
}

// Flat object of every parameter: {"rays.alpha": 0.02, ...}.
template <class Root>
nlohmann::json to_json(const ParamTable<Root>& table, const Root& root) {
    nlohmann::json settings = nlohmann::json::object();
    for (const Param<Root>& param : table.params())
        std::visit([&](auto value) { settings[param.info.name] = value; }, param.read(root));
    return settings;
}

// An INI file setting every parameter to its value in `values`, each key preceded by its doc,
// type, unit, range, built-in default and whether it is fixed at start.
template <class Root>
std::string sample_ini(const ParamTable<Root>& table, const Root& values) {
    std::string text =
        "; Every key is optional: a key left out keeps its built-in default.\n"
        "; Capacities size buffers and are fixed at start; tunables may change at run time.\n";
    for (std::string_view section : table.sections()) {
        text += "\n[" + std::string(section) + "]\n";
        for (const Param<Root>& param : table.params()) {
            const ParamInfo& info = param.info;
            if (info.section() != section) continue;
            text += "\n; " + std::string(info.doc) + "\n";
            text += "; " + describe_type_and_range(info) + ", default " + format_value(info.default_value) +
                    (info.kind == ParamKind::Capacity ? ", fixed at start\n" : ", tunable at run time\n");
            text += std::string(info.key()) + " = " + format_value(param.read(values)) + "\n";
        }
    }
    return text;
}

template <class Root>
std::vector<const ParamInfo*> list_params(const ParamTable<Root>& table) {
    std::vector<const ParamInfo*> infos;
    for (const Param<Root>& param : table.params()) infos.push_back(&param.info);
    return infos;
}

}  // namespace rays::config
