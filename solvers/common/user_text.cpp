#include "common/user_text.hpp"

#include <fmt/format.h>

namespace bb {
namespace {

constexpr size_t kMaxNameLength = 64;

// Length of the valid UTF-8 sequence at text[i] and its code point, or 0 when the bytes there are
// not one (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
size_t utf8_sequence(std::string_view text, size_t i, char32_t& cp) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) {
    cp = b0;
    return 1;
  }
  size_t n = 0;
  char32_t min = 0;
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2, cp = b0 & 0x1Fu, min = 0x80;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3, cp = b0 & 0x0Fu, min = 0x800;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4, cp = b0 & 0x07u, min = 0x10000;
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0u) != 0x80u) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3Fu);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

// C0 and C1 control characters and DEL.
bool is_control(char32_t cp) { return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F); }

bool name_char(char c, bool dot) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         (dot && c == '.');
}

std::string identifier_problem(std::string_view name, bool dot) {
  const std::string allowed =
      dot ? "ASCII letters, digits, '_', '-' and '.' (not first)" : "ASCII letters, digits, '_' and '-' (not first)";
  if (name.empty()) return fmt::format("an empty name; use 1 to {} {}", kMaxNameLength, allowed);
  if (name.size() > kMaxNameLength)
    return fmt::format("'{}' is longer than {} characters", printable(name), kMaxNameLength);
  for (char c : name)
    if (!name_char(c, dot))
      return fmt::format("'{}' holds {}; a name is 1 to {} {}", printable(name),
                         c == '/' || c == '\\' ? std::string("a path separator")
                         : c == '\0'           ? std::string("a NUL byte")
                         : c == '.'            ? std::string("a dot")
                         : c == ' '            ? std::string("a space")
                                               : fmt::format("the character '{}'", printable(std::string_view(&c, 1))),
                         kMaxNameLength, allowed);
  if (name.front() == '-' || (dot && name.front() == '.'))
    return fmt::format("'{}' starts with '{}'; a name is 1 to {} {}", printable(name), name.front(), kMaxNameLength,
                       allowed);
  return {};
}

}  // namespace

std::string name_problem(std::string_view name) { return identifier_problem(name, false); }

std::string dotted_name_problem(std::string_view name) { return identifier_problem(name, true); }

std::string label_problem(std::string_view text, bool multiline) {
  for (size_t i = 0; i < text.size();) {
    char32_t cp = 0;
    const size_t n = utf8_sequence(text, i, cp);
    if (n == 0) return fmt::format("'{}' is not valid UTF-8 (byte {})", printable(text), i + 1);
    if (is_control(cp) && !(multiline && (cp == '\n' || cp == '\t' || cp == '\r')))
      return fmt::format("'{}' holds the control character U+{:04X}", printable(text), static_cast<unsigned>(cp));
    i += n;
  }
  return {};
}

bool is_valid_utf8(std::string_view text) {
  for (size_t i = 0; i < text.size();) {
    char32_t cp = 0;
    const size_t n = utf8_sequence(text, i, cp);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string printable(std::string_view text, bool multiline) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    char32_t cp = 0;
    const size_t n = utf8_sequence(text, i, cp);
    if (n > 0 && (!is_control(cp) || cp == '\t' || (multiline && cp == '\n'))) {
      out.append(text.substr(i, n));
      i += n;
      continue;
    }
    for (size_t k = i; k < i + std::max<size_t>(n, 1); ++k)
      out += fmt::format("\\x{:02X}", static_cast<unsigned>(static_cast<unsigned char>(text[k])));
    i += std::max<size_t>(n, 1);
  }
  return out;
}

}  // namespace bb
