// SPDX-License-Identifier: Apache-2.0
// The one table of parameters for a settings struct `Root` (PX4 module.yaml style): each entry
// binds a ParamInfo to a field of Root. Parsing, validation, get/set by name, the JSON echo and
// the sample file are all generated from it (config_engine.hpp).
//
// A table is built section by section from member pointers:
//     table.section("rays", ParamKind::Tunable, [](TrackerConfig& c) -> auto& { return c.tunables.rays; })
//         .add("alpha", &RaysTunables::alpha, "", 0, 10, "first-order smoothness");
// and tables of separate structs combine with include() into the table of a struct holding both.
// A choice key binds to a std::string field, or to an enum field whose enumerators follow its words.
#pragma once
#include <cassert>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "config/cross_rule.hpp"
#include "config/param_info.hpp"
#include "config/param_text.hpp"

namespace rays::config {

template <class Root, class T>
using FieldAccess = std::function<T&(Root&)>;

// An enum field offered as a choice: its enumerator k is the k-th word of ParamInfo::choices.
template <class Root>
struct ChoiceAccess {
    std::function<int(const Root&)> get;
    std::function<void(Root&, int)> set;
};

// The k-th word of choices "a|b|c" (empty past the last), and the index of `word` (-1 if absent).
inline std::string_view choice_word(std::string_view choices, int k) {
    for (; k > 0 && choices.find('|') != std::string_view::npos; --k) choices.remove_prefix(choices.find('|') + 1);
    return k == 0 ? choices.substr(0, choices.find('|')) : std::string_view{};
}

inline int choice_index(std::string_view choices, std::string_view word) {
    for (int k = 0;; ++k) {
        if (choices.substr(0, choices.find('|')) == word) return k;
        if (choices.find('|') == std::string_view::npos) return -1;
        choices.remove_prefix(choices.find('|') + 1);
    }
}

template <class Root>
struct Param {
    ParamInfo info;
    // Alternatives in the order of ParamType and ParamValue; an enum choice last.
    std::variant<FieldAccess<Root, int>, FieldAccess<Root, double>, FieldAccess<Root, bool>,
                 FieldAccess<Root, std::string>, ChoiceAccess<Root>>
        field;

    ParamValue read(const Root& root) const {
        // The accessor hands out a reference; reading through it leaves `root` unchanged.
        Root& fields = const_cast<Root&>(root);
        return std::visit(
            [&](const auto& access) -> ParamValue {
                if constexpr (std::is_same_v<std::decay_t<decltype(access)>, ChoiceAccess<Root>>)
                    return std::string(choice_word(info.choices, access.get(root)));
                else
                    return access(fields);
            },
            field);
    }

    // `value` holds the parameter's own type (as parse_value makes it).
    void write(Root& root, const ParamValue& value) const {
        std::visit(
            [&](const auto& access) {
                if constexpr (std::is_same_v<std::decay_t<decltype(access)>, ChoiceAccess<Root>>) {
                    access.set(root, choice_index(info.choices, std::get<std::string>(value)));
                } else {
                    using T = std::remove_reference_t<decltype(access(root))>;
                    access(root) = std::get<T>(value);
                }
            },
            field);
    }
};

struct RuleViolation {
    const CrossRule* rule;
    std::string message;
};

template <class Root>
class ParamTable {
public:
    // Adds the fields of one part of Root (a nested struct) under [name].
    template <class Part>
    class Section {
    public:
        Section(ParamTable& table, std::string name, ParamKind kind, std::function<Part&(Root&)> part)
            : table_(table), name_(std::move(name)), kind_(kind), part_(std::move(part)) {}

        template <class T>
        Section& add(std::string_view key, T Part::*member, std::string_view unit, double min, double max,
                     std::string_view doc) {
            ParamInfo info{name_ + "." + std::string(key), param_type_of<T>(), kind_, unit, min, max, {}, std::string(doc), {}};
            table_.add(std::move(info), FieldAccess<Root, T>([part = part_, member](Root& root) -> T& {
                           return part(root).*member;
                       }));
            return *this;
        }

        Section& add(std::string_view key, bool Part::*member, std::string_view doc) {
            return add(key, member, "", 0.0, 1.0, doc);
        }

        // A one-line text, such as a path.
        Section& add(std::string_view key, std::string Part::*member, std::string_view doc) {
            return add(key, member, "", 0.0, 0.0, doc);
        }

        // One word of `choices` ("v4l2|replay").
        Section& add_choice(std::string_view key, std::string Part::*member, std::string_view choices,
                            std::string_view doc) {
            add(key, member, doc);
            table_.params_.back().info.type = ParamType::Choice;
            table_.params_.back().info.choices = choices;
            return *this;
        }

        // One word of `choices` for an enum field: its enumerator k is the k-th word ("rays|snake").
        template <class E>
            requires std::is_enum_v<E>
        Section& add_choice(std::string_view key, E Part::*member, std::string_view choices, std::string_view doc) {
            ParamInfo info{name_ + "." + std::string(key), ParamType::Choice, kind_, "", 0.0, 0.0, {}, std::string(doc),
                           choices};
            table_.add(std::move(info),
                       ChoiceAccess<Root>{[part = part_, member](const Root& root) {
                                              return static_cast<int>(part(const_cast<Root&>(root)).*member);
                                          },
                                          [part = part_, member](Root& root, int k) {
                                              part(root).*member = static_cast<E>(k);
                                          }});
            return *this;
        }

    private:
        ParamTable& table_;
        std::string name_;
        ParamKind kind_;
        std::function<Part&(Root&)> part_;
    };

    // `part` is a member pointer of Root or a callable returning a reference into Root.
    template <class Access>
    auto section(std::string_view name, ParamKind kind, Access part) {
        using Part = std::remove_reference_t<std::invoke_result_t<Access, Root&>>;
        return Section<Part>(*this, std::string(name), kind, std::function<Part&(Root&)>(part));
    }

    void add_rule(CrossRule rule) {
        for ([[maybe_unused]] const std::string& key : rule.keys) assert(find(key) != nullptr);
        rules_.push_back(std::move(rule));
    }

    // Takes over every parameter and rule of `inner`, a table of the part of Root that `part` returns.
    template <class Inner, class Access>
    void include(const ParamTable<Inner>& inner, Access part) {
        std::function<Inner&(Root&)> to_inner(part);
        for (const Param<Inner>& param : inner.params()) {
            std::visit(
                [&](const auto& access) {
                    if constexpr (std::is_same_v<std::decay_t<decltype(access)>, ChoiceAccess<Inner>>) {
                        add(param.info, ChoiceAccess<Root>{[get = access.get, to_inner](const Root& root) {
                                                               return get(to_inner(const_cast<Root&>(root)));
                                                           },
                                                           [set = access.set, to_inner](Root& root, int k) {
                                                               set(to_inner(root), k);
                                                           }});
                    } else {
                        using T = std::remove_reference_t<decltype(access(std::declval<Inner&>()))>;
                        add(param.info, FieldAccess<Root, T>([access, to_inner](Root& root) -> T& {
                                return access(to_inner(root));
                            }));
                    }
                },
                param.field);
        }
        for (const CrossRule& rule : inner.rules()) add_rule(rule);
    }

    const std::vector<Param<Root>>& params() const { return params_; }
    const std::vector<CrossRule>& rules() const { return rules_; }

    const Param<Root>* find(std::string_view name) const {
        for (const Param<Root>& param : params_)
            if (param.info.name == name) return &param;
        return nullptr;
    }

    // Section names in the order they first appear.
    std::vector<std::string_view> sections() const {
        std::vector<std::string_view> names;
        for (const Param<Root>& param : params_) {
            std::string_view name = param.info.section();
            if (!contains(names, name)) names.push_back(name);
        }
        return names;
    }

    std::vector<std::string_view> names() const {
        std::vector<std::string_view> all;
        for (const Param<Root>& param : params_) all.push_back(param.info.name);
        return all;
    }

    // The first rule `root` breaks.
    std::optional<RuleViolation> check_rules(const Root& root) const {
        ParamLookup lookup = [&](std::string_view name) { return value_as_number(find(name)->read(root)); };
        for (const CrossRule& rule : rules_)
            if (auto message = rule.check(lookup)) return RuleViolation{&rule, std::move(*message)};
        return std::nullopt;
    }

private:
    template <class T>
    void add(ParamInfo info, FieldAccess<Root, T> access) {
        assert(find(info.name) == nullptr);
        Root defaults{};
        info.default_value = access(defaults);
        params_.push_back(Param<Root>{std::move(info), {}});
        params_.back().field.template emplace<FieldAccess<Root, T>>(std::move(access));
    }

    void add(ParamInfo info, ChoiceAccess<Root> access) {
        assert(find(info.name) == nullptr);
        info.default_value = std::string(choice_word(info.choices, access.get(Root{})));
        params_.push_back(Param<Root>{std::move(info), {}});
        params_.back().field.template emplace<ChoiceAccess<Root>>(std::move(access));
    }

    static bool contains(const std::vector<std::string_view>& names, std::string_view name) {
        for (std::string_view known : names)
            if (known == name) return true;
        return false;
    }

    std::vector<Param<Root>> params_;
    std::vector<CrossRule> rules_;
};

}  // namespace rays::config
