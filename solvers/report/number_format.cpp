#include "report/number_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string_view>
#include <utility>

namespace bb {
namespace {

// Between a number and its unit: no line break inside a quantity in a narrow table cell.
constexpr std::string_view kNbsp = "\u00a0";

// "5.63e-05" -> "5.63e-5", "1e+06" -> "1e6": the exponent as engineers write it.
std::string clean_exponent(std::string text) {
  const size_t e = text.find('e');
  if (e == std::string::npos) return text;
  std::string mantissa = text.substr(0, e);
  std::string exponent = text.substr(e + 1);
  const bool negative = exponent.front() == '-';
  if (exponent.front() == '-' || exponent.front() == '+') exponent.erase(0, 1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() > suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

}  // namespace

std::string unit_of_column(const std::string& column) {
  // Longest suffixes first: "_n_per_m" before "_m", "_amp_per_n" before "_n".
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 15> kSuffixes{{
      {"_n_per_m", "N/m"},
      {"_amp_per_n", "m/N"},
      {"_m_per_n", "m/N"},
      {"_rad_s", "rad/s"},
      {"_per_s", "1/s"},
      {"_hz", "Hz"},
      {"_deg", "deg"},
      {"_rad", "rad"},
      {"_pa", "Pa"},
      {"_kg", "kg"},
      {"_j", "J"},
      {"_w", "W"},
      {"_n", "N"},
      {"_m", "m"},
      {"_s", "s"},
  }};
  std::string lower;
  for (char c : column) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "ux" || lower == "uy" || lower == "uz") return "m";
  if (lower.size() == 3 && lower[0] == 's' && std::string_view("xyz").find(lower[1]) != std::string_view::npos &&
      std::string_view("xyz").find(lower[2]) != std::string_view::npos)
    return "Pa";  // stress components sxx, syy, sxy, ...
  if (lower == "von_mises") return "Pa";
  for (const auto& [suffix, unit] : kSuffixes)
    if (ends_with(lower, suffix)) return std::string(unit);
  return "";
}

std::string format_setting(double value) { return fmt::format("{:.6g}", value); }

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0.0) return "0";
  return clean_exponent(fmt::format("{:.5g}", value));
}

std::string format_quantity(double value, const std::string& unit) {
  return unit.empty() ? format_number(value) : fmt::format("{}{}{}", format_number(value), kNbsp, unit);
}

std::string format_percent(double fraction) {
  if (std::isnan(fraction)) return "nan";
  if (std::isinf(fraction)) return fraction > 0 ? "+inf" : "-inf";
  const double p = 100.0 * fraction;
  if (p == 0.0) return fmt::format("0{}%", kNbsp);
  if (std::abs(p) >= 0.01) return fmt::format("{:+.2f}{}%", p, kNbsp);
  return fmt::format("{}{}%", clean_exponent(fmt::format("{:+.1e}", p)), kNbsp);
}

std::string format_seconds(double seconds) {
  if (!std::isfinite(seconds)) return fmt::format("{}{}s", format_number(seconds), kNbsp);
  if (seconds < 0.1) return fmt::format("{}{}s", clean_exponent(fmt::format("{:.2g}", seconds)), kNbsp);
  if (seconds < 3600.0) return fmt::format("{:.1f}{}s", seconds, kNbsp);
  const long minutes = std::lround(seconds / 60.0);
  return fmt::format("{}{}h {:02d}{}min", minutes / 60, kNbsp, static_cast<int>(minutes % 60), kNbsp);
}

std::string format_share(double used) {
  if (std::isnan(used)) return "-";
  return std::isfinite(used) ? fmt::format("{:.2f}", std::max(used, 0.0)) : std::string("inf");
}

std::string share_cell(double used) {
  if (std::isnan(used)) return "-";
  return fmt::format("`{}`{}{}", tolerance_bar(used), kNbsp, format_share(used));
}

std::string tolerance_bar(double used, int cells) {
  static constexpr std::array<std::string_view, 9> kEighths{"", "▏", "▎", "▍", "▌", "▋", "▊", "▉", "█"};
  const double clamped = std::isnan(used) ? 0.0 : std::clamp(used, 0.0, 1.0);
  const long eighths = std::lround(clamped * cells * 8);
  std::string bar;
  int drawn = 0;
  for (; drawn < eighths / 8; ++drawn) bar += kEighths[8];
  if (eighths % 8 != 0) {
    bar += kEighths[static_cast<size_t>(eighths % 8)];
    ++drawn;
  }
  for (; drawn < cells; ++drawn) bar += "░";
  return bar;
}

}  // namespace bb
