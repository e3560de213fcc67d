// HTML report text; plain CSS in the page, no scripts, so it opens offline in any browser.
#include "compare/report_html.h"

#include <fmt/core.h>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace raintrace::compare {

namespace {

std::string url_encode(const std::string& text) {
  std::string out;
  for (unsigned char ch : text) {
    if (std::isalnum(ch) || ch == '-' || ch == '_' || ch == '.' || ch == '~' || ch == '/') {
      out += char(ch);
    } else {
      out += fmt::format("%{:02X}", ch);
    }
  }
  return out;
}

std::string figure(const std::string& caption, const std::string& href, const std::string& file) {
  if (file.empty()) {
    return fmt::format(
        "<figure><div class=\"none\">no image</div><figcaption>{}</figcaption>"
        "</figure>",
        caption);
  }
  return fmt::format(
      "<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a><figcaption>{1}</figcaption>"
      "</figure>",
      href + "/" + url_encode(file), caption);
}

std::string num(double v, const char* spec = "{:.6g}") {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt::format(fmt::runtime(spec), v);
}

constexpr const char* kStyle =
    R"(body{font-family:sans-serif;margin:1.5em;background:#f4f4f4;color:#222}
section{background:#fff;border-left:8px solid #888;margin:1em 0;padding:.6em 1em}
section.PASS{border-color:#2a2}section.WARN{border-color:#d90}
section.FAIL,section.MISSING,section.ERROR{border-color:#c22}
.badge{font-weight:bold;padding:.1em .5em;border-radius:.3em;color:#fff;background:#888}
.PASS .badge{background:#2a2}.WARN .badge{background:#d90}
.FAIL .badge,.MISSING .badge,.ERROR .badge{background:#c22}
.row{display:flex;flex-wrap:wrap;gap:1em}figure{margin:0}
img{image-rendering:pixelated;min-width:300px;max-width:100%;border:1px solid #ccc}
.none{width:300px;height:169px;display:flex;align-items:center;justify-content:center;background:#ddd}
table{border-collapse:collapse;margin:.5em 0}td,th{padding:.15em .6em;text-align:right;border-bottom:1px solid #eee}
th{text-align:left}code{word-break:break-all})";

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
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
      case '\'':
        out += "&#39;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

std::filesystem::path html_assets_dir(const std::filesystem::path& html_file) {
  return html_file.parent_path() / (html_file.stem().string() + "_files");
}

std::string to_html(const CompareReport& report, const std::string& assets_href) {
  const Thresholds& t = report.thresholds;
  int failing = 0;
  for (const auto& f : report.frames) failing += f.failed() || f.status == FrameStatus::error;
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      "<title>raintrace compare: {} frame(s), {} not passing</title>\n<style>{}</style></head>\n"
      "<body>\n<h1>raintrace compare</h1>\n<p>Reference <code>{}</code> vs candidate "
      "<code>{}</code>: {} frame(s), <b>{}</b> not passing.</p>\n"
      "<p>A value fails when |A&minus;B| &gt; {:g}, a frame when more than {:g}% of its pixels "
      "fail; warnings at {:g} and {:g}%.</p>\n",
      report.frames.size(), failing, kStyle, html_escape(report.a.string()),
      html_escape(report.b.string()), report.frames.size(), failing, t.fail, t.fail_percent, t.warn,
      t.warn_percent);
  for (const auto& f : report.frames) {
    const std::string verdict = f.verdict_string();
    out += fmt::format("<section class=\"{}\">\n<h2>{} <span class=\"badge\">{}</span></h2>\n",
                       verdict, html_escape(f.name), verdict);
    if (f.status == FrameStatus::compared) {
      const Metrics& m = f.metrics;
      out += fmt::format(
          "<table><tr><th>mean error</th><td>{}</td><th>max error</th><td>{} at ({}, {}) "
          "channel {}</td></tr>\n<tr><th>RMSE</th><td>{}</td><th>PSNR</th><td>{} dB</td></tr>\n"
          "<tr><th>SSIM</th><td>{}</td><th>pixels over warn / fail</th><td>{} ({}%) / {} "
          "({}%)</td></tr></table>\n",
          num(m.mean_error), num(m.max_error), m.max_x, m.max_y, m.max_c, num(m.rmse),
          m.display_metrics ? num(m.psnr, "{:.2f}") : "&ndash;",
          m.display_metrics ? num(m.ssim, "{:.5f}") : "&ndash;", m.warn_pixels,
          num(m.warn_percent, "{:.3f}"), m.fail_pixels, num(m.fail_percent, "{:.3f}"));
      for (const std::string* how : {&f.developed_a, &f.developed_b}) {
        if (how->empty()) continue;
        out += fmt::format("<p>{} is HDR, developed for comparison: <code>{}</code></p>\n",
                           how == &f.developed_a ? "Reference" : "Candidate", html_escape(*how));
      }
    } else if (f.status == FrameStatus::error) {
      out += fmt::format("<p>Error: {}</p>\n", html_escape(f.error));
    } else {
      out += fmt::format("<p>Present only in <code>{}</code>.</p>\n",
                         html_escape((f.a.empty() ? report.b : report.a).string()));
    }
    out += "<div class=\"row\">" + figure("reference", assets_href, f.asset_reference) +
           figure("candidate", assets_href, f.asset_candidate) +
           figure("difference", assets_href, f.asset_diff) + "</div>\n</section>\n";
  }
  out += "</body></html>\n";
  return out;
}

void write_html(const std::filesystem::path& html_file, const CompareReport& report) {
  const std::string text =
      to_html(report, url_encode(html_assets_dir(html_file).filename().string()));
  std::filesystem::path tmp = html_file;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", tmp.string()));
  }
  std::filesystem::rename(tmp, html_file);
}

}  // namespace raintrace::compare
