// Settings given on the command line (`run --set analysis.harmonics=13`): a case run at another
// setting without a copy of its file, which would lose the relative paths of its references and
// model (a copy placed elsewhere fails its checks' reads).
#pragma once
#include <toml++/toml.h>

#include <string>
#include <vector>

namespace bb {

// Each "dotted.key=VALUE" (VALUE in TOML syntax: 13, 1e-3, "events", [1, 2]) replaces or adds the
// key in `root`; each "dotted.key" of `removals` (`run --unset`) removes a key or a whole table
// that must exist. Every table on the way must exist; an array of tables is entered by index
// (analysis.contact.0.mu). Throws InputError naming the
// setting. The values carry no source line: messages about them name the case file alone.
void apply_settings(toml::table& root, const std::vector<std::string>& settings,
                    const std::vector<std::string>& removals = {});

}  // namespace bb
