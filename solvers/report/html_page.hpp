// Reports readable without a Markdown viewer: report.md and index.md rendered as HTML pages that
// carry their plots inside (one file to mail or archive) and link to each other's HTML.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bb {

// RFC 4648 base64 (with padding), the encoding of the pages' data: URIs.
std::string base64(std::string_view bytes);

// GitHub-flavoured Markdown (tables included) to an HTML fragment. Raw HTML in the Markdown is not
// passed through (cmark-gfm's safe mode), so a label in a case file cannot inject markup; the one
// exception is a folded section: a line `<details><summary>TEXT</summary>` (TEXT escaped) and its
// closing line `</details>`, each on its own.
std::string markdown_to_html(const std::string& markdown);

// A page inlines an SVG of at most kMaxInlineSvgBytes, and kMaxInlinedBytes of them in all (the
// shipped reports' largest plot is well under 1 MB): a larger one stays a link to its file, so that a
// huge plot cannot make a page of gigabytes.
inline constexpr std::uintmax_t kMaxInlineSvgBytes = 8'000'000, kMaxInlinedBytes = 64'000'000;

// The complete page for `markdown`, whose relative links are relative to `folder`: every local SVG
// image that exists there becomes a data: URI when `inline_images` (a missing one keeps its path,
// so a browser shows it missing; one above the sizes above stays a link, named in `notes`), and links
// to `report.md` / `index.md` point at their HTML twins.
std::string html_page(const std::string& markdown, const std::filesystem::path& folder, bool inline_images = true,
                      std::vector<std::string>* notes = nullptr);

// Writes `<markdown_file minus .md>.html` beside `markdown_file`, atomically; an index.md's images
// stay links (thumbnails of the reports' plots).
void write_html_twin(const std::filesystem::path& markdown_file, std::vector<std::string>* notes = nullptr);

// The HTML twin of every report.md and index.md under `folder` (reports written before their
// pages were, or edited by hand); returns the Markdown files rendered, in path order.
std::vector<std::filesystem::path> write_html_twins(const std::filesystem::path& folder,
                                                    std::vector<std::string>* notes = nullptr);

}  // namespace bb
