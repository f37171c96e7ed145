// Text that comes from the user (names and labels in case files, bytes echoed from meshes, reference
// and measured-data files, file names) made safe for the places it ends up: file and folder names,
// CSV headers, DOF names, terminal messages, report.md and summary.json.
//
// Two kinds of user text, documented in cases/README.md ("Names and labels"):
// - a *name* (a set, a reduced model, a contact, a damper point; a case, whose name is its report
//   folder) becomes part of file names, CSV column names and DOF names ("tip.x"): 1 to 64 ASCII
//   letters, digits, '_' and '-', not starting with '-'. A case name and a node label of a
//   reduced model may also hold '.', not first.
//   This leaves no room for "..", "/", absolute paths, NUL bytes, quotes or spaces.
// - a *label* (a check name, a title, a column name, a data set's name) is only shown: any UTF-8
//   text without control characters. Braces are harmless: user text is never a format string.
#pragma once
#include <string>
#include <string_view>

namespace bb {

// Why `name` cannot be a name ("" when it can).
std::string name_problem(std::string_view name);
// Why `name` cannot be a name that may also hold '.', not first ("" when it can): a case name,
// which names the case's report folder, and a node label in a reduced model ("root.7").
std::string dotted_name_problem(std::string_view name);
// Why `text` cannot be a label ("" when it can); `multiline` admits line breaks and tabs (a
// Markdown description).
std::string label_problem(std::string_view text, bool multiline = false);

bool is_valid_utf8(std::string_view text);

// `text` as it may be echoed: valid UTF-8 is kept, and so are tabs (and line breaks with
// `multiline`: a whole report); every other control character and every byte that is not part of
// valid UTF-8 is written as \xHH. Messages, reports and JSON show user bytes only through this
// function (or after it).
std::string printable(std::string_view text, bool multiline = false);

}  // namespace bb
