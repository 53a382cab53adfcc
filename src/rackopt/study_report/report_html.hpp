// report.html of a study: report.md rendered to HTML by cmark-gfm (the
// GitHub-flavoured Markdown that report.md is written in, tables included)
// inside one self-contained document that an engineer can mail: inline CSS,
// every plot inlined as SVG markup, nothing loaded from anywhere (a
// Content-Security-Policy forbids it even if a study's text tried).
// docs/output.md, "Study results".
#pragma once

#include <map>
#include <string>

namespace rackopt::study_report {

// The HTML document of `markdown` under the title `title`. Each image of the
// markdown whose link target is a key of `svg_by_target` becomes a figure
// holding that SVG markup (as inline_svg returns it) and the image's alt
// text as its caption; any other image becomes a plain link to its target,
// so the document never refers to an image it does not contain. Raw HTML in
// the markdown (a study's description may hold some) is shown as text,
// never interpreted.
std::string report_html(const std::string& markdown, const std::string& title,
                        const std::map<std::string, std::string>& svg_by_target);

// An SVG file's text made fit to sit inside an HTML document: what precedes
// the <svg> element (XML declaration, doctype, comments) is dropped; the root's
// fixed width and height are dropped when it has a viewBox, so the page's CSS
// scales it; every id, and every reference to one (href="#..", url(#..)),
// gets `id_prefix`, so that several plots in one page (gnuplot names its
// point symbols alike in every file) cannot take each other's definitions.
// "" when the text holds no <svg> element.
std::string inline_svg(const std::string& svg_text, const std::string& id_prefix);

// `text` with &, <, >, " and ' as character references.
std::string html_escape(const std::string& text);

}  // namespace rackopt::study_report
