// Numbers in reports as engineers write them (174.74 Hz, -0.55 %, 5.63e-5 m/N, 1.2 s); the CSV
// files keep full precision. A no-break space (U+00A0) joins a number to its unit.
#pragma once
#include <string>

namespace bb {

// The SI unit a result column's name implies by its suffix ("frequency_hz" -> "Hz", "ux" -> "m",
// "stick_slope_n_per_m" -> "N/m", "peak_amp_per_n" -> "m/N"); "" for a ratio, count or unknown.
std::string unit_of_column(const std::string& column);

// Five significant digits, trailing zeros dropped, exponent without padding: 174.74, 0.018021,
// 5.63e-5, 1e6; "nan", "inf" and "-inf" as such.
std::string format_number(double value);
// format_number with the unit after a space, when there is one.
std::string format_quantity(double value, const std::string& unit);
// Six significant digits as printf's %g writes them: a setting echoed in a report's description.
std::string format_setting(double value);
// A fraction as a percentage with its sign: +0.54 %, -12.30 %, +2.0e-6 %, 0 %.
std::string format_percent(double fraction);
// A duration: 0.013 s, 1.2 s, 372.6 s, 1 h 02 min.
std::string format_seconds(double seconds);

// The share of its tolerance an entry uses (checks/checks.hpp, tolerance_used): "0.96", "inf"; a
// negative share (inside a one-sided bound) as 0, NaN (no entry) as "-".
std::string format_share(double used);
// The share as a bar and its number ("`█████████▋` 0.96"), or "-" for NaN: a table cell.
std::string share_cell(double used);

// How much of its tolerance an error uses (0 none, 1 all of it, above 1 a miss) as a bar of `cells`
// character cells (eighths of a cell by Unicode block elements), full beyond 1: "█████▌░░░░".
std::string tolerance_bar(double used, int cells = 10);

}  // namespace bb
