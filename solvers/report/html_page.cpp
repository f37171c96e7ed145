#include "report/html_page.hpp"

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/user_text.hpp"
#include "report/output_folder.hpp"

namespace bb {
namespace fs = std::filesystem;
namespace {

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw OutputError("cannot read " + file.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Title of the page: the Markdown's first level-1 heading, else "bladebench report".
std::string title_of(const std::string& markdown) {
  std::istringstream in(markdown);
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("# ")) return line.substr(2);
  return "bladebench report";
}

std::string escape_html(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// The value of every `attribute="..."` in `html` passed through `change` (cmark-gfm writes
// attributes with double quotes and escapes quotes inside them).
template <class Change>
std::string rewrite_attribute(const std::string& html, std::string_view attribute, Change change) {
  const std::string opening = std::string(attribute) + "=\"";
  std::string out;
  size_t from = 0;
  for (size_t at; (at = html.find(opening, from)) != std::string::npos;) {
    const size_t value = at + opening.size();
    const size_t close = html.find('"', value);
    if (close == std::string::npos) break;
    out.append(html, from, value - from);
    out += change(html.substr(value, close - value));
    from = close;
  }
  out.append(html, from);
  return out;
}

bool is_local(const std::string& target) { return target.find(':') == std::string::npos && !target.starts_with('/'); }

// Local SVG images inlined (a missing one keeps its path) unless `inline_images` is false, up to the
// sizes html_page.hpp states (a larger one stays a link, noted in `notes`); links to other Markdown
// reports sent to their HTML pages.
std::string rewrite_references(const std::string& html, const fs::path& folder, bool inline_images,
                               std::vector<std::string>* notes) {
  const std::string linked = rewrite_attribute(html, "href", [](std::string target) {
    if (is_local(target) && (target.ends_with("report.md") || target.ends_with("index.md")))
      target.replace(target.size() - 3, 3, ".html");
    return target;
  });
  if (!inline_images) return linked;
  std::uintmax_t inlined = 0;
  return rewrite_attribute(linked, "src", [&](const std::string& target) {
    const fs::path file = folder / target;
    if (!is_local(target) || !target.ends_with(".svg") || !file_problem(file).empty()) return target;
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec || size > kMaxInlineSvgBytes || inlined + size > kMaxInlinedBytes) {
      if (notes)
        notes->push_back(fmt::format("{}: {:.3g} MB, linked, not inlined (a page inlines SVGs of at most {} MB, {} MB "
                                     "in all)",
                                     printable(file.string()), static_cast<double>(size) / 1e6,
                                     kMaxInlineSvgBytes / 1000000, kMaxInlinedBytes / 1000000));
      return target;
    }
    inlined += size;
    return "data:image/svg+xml;base64," + base64(read_bytes(file));
  });
}

// GitHub-flavoured Markdown to HTML with cmark-gfm in its safe mode.
std::string render_markdown(const std::string& markdown) {
  cmark_gfm_core_extensions_ensure_registered();
  const std::unique_ptr<cmark_parser, decltype(&cmark_parser_free)> parser(cmark_parser_new(CMARK_OPT_DEFAULT),
                                                                           &cmark_parser_free);
  for (const char* name : {"table", "autolink", "strikethrough"})
    if (cmark_syntax_extension* ext = cmark_find_syntax_extension(name))
      cmark_parser_attach_syntax_extension(parser.get(), ext);
  cmark_parser_feed(parser.get(), markdown.data(), markdown.size());
  const std::unique_ptr<cmark_node, decltype(&cmark_node_free)> root(cmark_parser_finish(parser.get()),
                                                                     &cmark_node_free);
  if (!root) throw std::runtime_error("the Markdown parser returned no document");
  char* html = cmark_render_html(root.get(), CMARK_OPT_DEFAULT, cmark_parser_get_syntax_extensions(parser.get()));
  const std::string out(html);
  std::free(html);
  return out;
}

constexpr std::string_view kStyle = R"css(
body { font-family: sans-serif; max-width: 70em; margin: 1em auto; padding: 0 1em; line-height: 1.45; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.92em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; text-align: left; }
th { background: #eee; }
code { background: #f4f4f4; padding: 0 0.2em; }
blockquote { border-left: 4px solid #c60; margin-left: 0; padding-left: 1em; }
img { max-width: 100%; max-height: 27em; }
p > img:has(+ img), p > img + img { max-width: 49.5%; }
td img { width: 14em; height: auto; }
summary { cursor: pointer; font-weight: bold; margin: 0.5em 0; }
)css";

}  // namespace

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    for (int shift : {18, 12, 6, 0}) out += kAlphabet[(v >> shift) & 63];
  }
  if (const size_t rest = bytes.size() - i; rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string markdown_to_html(const std::string& markdown) {
  // Folded sections are the one markup let through: a line `<details><summary>TEXT</summary>` or
  // `</details>` on its own, TEXT escaped; the Markdown between them is rendered on its own.
  constexpr std::string_view kOpen = "<details><summary>", kSummaryEnd = "</summary>", kClose = "</details>";
  std::string html, chunk;
  int open = 0;
  std::istringstream in(markdown);
  for (std::string line; std::getline(in, line);) {
    const bool opens = line.starts_with(kOpen) && line.ends_with(kSummaryEnd);
    const bool closes = line == kClose && open > 0;
    if (!opens && !closes) {
      chunk += line + '\n';
      continue;
    }
    html += render_markdown(chunk);
    chunk.clear();
    if (opens) {
      ++open;
      html +=
          "<details><summary>" +
          escape_html(std::string_view(line).substr(kOpen.size(), line.size() - kOpen.size() - kSummaryEnd.size())) +
          "</summary>\n";
    } else {
      --open;
      html += "</details>\n";
    }
  }
  html += render_markdown(chunk);
  for (; open > 0; --open) html += "</details>\n";
  return html;
}

std::string html_page(const std::string& markdown, const fs::path& folder, bool inline_images,
                      std::vector<std::string>* notes) {
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>";
  page += escape_html(title_of(markdown));
  page += "</title>\n<style>";
  page += kStyle;
  page += "</style>\n</head>\n<body>\n";
  page += rewrite_references(markdown_to_html(markdown), folder, inline_images, notes);
  page += "</body>\n</html>\n";
  return page;
}

void write_html_twin(const fs::path& markdown_file, std::vector<std::string>* notes) {
  fs::path html_file = markdown_file;
  html_file.replace_extension(".html");
  // The index links its cases' plots as thumbnails: inlined, they would make it the size of all reports.
  const bool inline_images = markdown_file.filename() != "index.md";
  write_file_atomically(html_file,
                        html_page(read_bytes(markdown_file), markdown_file.parent_path(), inline_images, notes));
}

std::vector<fs::path> write_html_twins(const fs::path& folder, std::vector<std::string>* notes) {
  std::vector<fs::path> pages;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    if (e.path().filename() != "report.md" && e.path().filename() != "index.md") continue;
    // A page that is a link loop or a device is named, not thrown as a filesystem error.
    if (const std::string why = file_problem(e.path()); why.empty())
      pages.push_back(e.path());
    else if (why != "it is a directory")
      throw InputError(fmt::format("{}: cannot open ({})", printable(e.path().string()), why));
  }
  std::sort(pages.begin(), pages.end());
  for (const fs::path& md : pages) write_html_twin(md, notes);
  return pages;
}

}  // namespace bb
