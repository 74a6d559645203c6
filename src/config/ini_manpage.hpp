// SPDX-License-Identifier: Apache-2.0
// raysd.ini(5) in roff, written from the parameter table that sample_ini and the INI reader use, so
// the manual page, the sample file and what the reader accepts cannot drift apart
// (docs/man/raysd.ini.5 is this text; tests/daemon/test_manpages.cpp keeps it so).
#pragma once
#include <string>
#include <string_view>

#include "config/param_table.hpp"
#include "config/param_text.hpp"

namespace rays::config {

// Text safe in a roff line: backslashes escaped, minus signs as \-, and a leading '.' or '\''
// (which roff would read as a request) protected by \&.
inline std::string roff_text(std::string_view text) {
    std::string out;
    if (!text.empty() && (text.front() == '.' || text.front() == '\'')) out += "\\&";
    for (char c : text) {
        if (c == '\\') out += "\\e";
        else if (c == '-') out += "\\-";
        else out += c;
    }
    return out;
}

// The page: what the file is, then every section and key with its doc, type, range, unit, built-in
// default, the value raysd.ini ships with (`shipped`) and whether it is fixed at start.
template <class Root>
std::string ini_manpage(const ParamTable<Root>& table, const Root& shipped, std::string_view version) {
    std::string text =
        ".\\\" SPDX-License-Identifier: Apache-2.0\n"
        ".\\\" Generated from raysd's parameter table (src/config/ini_manpage.hpp); do not edit.\n"
        ".TH RAYSD.INI 5 \"\" \"raysd " + std::string(version) + "\" \"raysd manual\"\n"
        ".SH NAME\n"
        "raysd.ini \\- configuration file of the raysd tracking daemon\n"
        ".SH SYNOPSIS\n"
        ".B /etc/raysd/raysd.ini\n"
        ".SH DESCRIPTION\n"
        "An INI file:\n"
        ".B [section]\n"
        "lines, then\n"
        ".I key\n"
        "=\n"
        ".I value\n"
        "lines; a line starting with ; or # is a comment.\n"
        "Every key is optional: a key left out keeps its built\\-in default.\n"
        "Unknown sections and keys, values of the wrong type or out of range, a key set twice and\n"
        "settings that contradict each other are errors:\n"
        ".B raysd\n"
        "names the file and the line, and exits with status 78 (EX_CONFIG) without starting.\n"
        ".B raysd \\-\\-check\\-config\n"
        ".I FILE\n"
        "checks a file the same way.\n"
        ".PP\n"
        ".I Capacities\n"
        "size the daemon's buffers and are fixed when it starts (change them and restart).\n"
        ".I Tunables\n"
        "may change while it runs: edit the file and reload\n"
        "(\\fBsystemctl reload raysd\\fR, which sends SIGHUP), or set one with\n"
        "\\fBraysctl set\\fR \\fINAME VALUE\\fR until the next reload.\n"
        "The names are \\fIsection\\fR.\\fIkey\\fR, as\n"
        "\\fBraysctl get\\fR lists them.\n"
        ".PP\n"
        "The installed file is a template for a real rig: every key below, documented, set to the value\n"
        "shown as \\(lqshipped\\(rq (a V4L2 camera and a Modbus unit; a real install never falls back to the\n"
        "simulation). \\fBraysd \\-\\-sample\\-config\\fR prints the same keys and values.\n";
    for (std::string_view section : table.sections()) {
        text += ".SH [" + roff_text(section) + "]\n";
        for (const Param<Root>& param : table.params()) {
            const ParamInfo& info = param.info;
            if (info.section() != section) continue;
            text += ".TP\n.B " + roff_text(info.key()) + "\n";
            text += roff_text(info.doc) + ".\n.br\n";
            std::string facts = describe_type_and_range(info) + "; default " + format_value(info.default_value);
            std::string value = format_value(param.read(shipped));
            if (value != format_value(info.default_value)) facts += "; shipped " + value;
            facts += info.kind == ParamKind::Capacity ? "; fixed at start." : "; tunable at run time.";
            text += roff_text(facts) + "\n";
        }
    }
    text +=
        ".SH FILES\n"
        ".TP\n"
        ".I /etc/raysd/raysd.ini\n"
        "the configuration\n"
        "(\\fBExecStart=\\fR of raysd.service names it; a site's other file goes in a drop\\-in).\n"
        ".SH SEE ALSO\n"
        ".BR raysd (8),\n"
        ".BR raysctl (1),\n"
        ".BR ptu\\-sim (1),\n"
        ".BR rays\\-replay (1)\n";
    return text;
}

}  // namespace rays::config
