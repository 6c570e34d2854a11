#include "report_html.h"
#include "kit_folders.h"

#include <cctype>
#include <filesystem>
#include <regex>
#include <set>
#include <string_view>

namespace raylab::grading {
namespace {

// What the stage code printed, at most (the rest is cut, and the page says how much there was).
constexpr std::size_t kShownOutputBytes = 16384;

// The page's look: the system's own fonts (with the usual Chinese ones), nothing loaded.
constexpr const char* kStyle = R"css(
:root { --ok: #1a7f37; --bad: #cf222e; --none: #6e7781; --lost: #bc4c00; --line: #d0d7de; --soft: #f6f8fa;
        --muted: #57606a; }
* { box-sizing: border-box; }
body { margin: 0; background: #fff; color: #1f2328;
       font: 16px/1.55 system-ui, -apple-system, "Segoe UI", Roboto, "Noto Sans", "Noto Sans CJK SC", "PingFang SC",
             "Microsoft YaHei", "WenQuanYi Micro Hei", sans-serif; }
main { max-width: 1120px; margin: 0 auto; padding: 24px 20px 48px; }
h1 { font-size: 1.5rem; margin: 0 0 2px; }
.total { font-size: 1.15rem; margin: 0 0 18px; color: var(--muted); }
.total strong { font-size: 2rem; color: #1f2328; font-variant-numeric: tabular-nums; }
a { color: #0969da; }
code, pre, .id { font-family: ui-monospace, "DejaVu Sans Mono", Menlo, Consolas, "Noto Sans Mono CJK SC", monospace; }
table.scores { border-collapse: collapse; width: 100%; margin: 0 0 12px; }
table.scores th, table.scores td { text-align: left; padding: 7px 12px; border-bottom: 1px solid var(--line);
                                   vertical-align: middle; }
table.scores thead th { background: var(--soft); font-weight: 600; }
table.scores tfoot th, table.scores tfoot td { font-weight: 700; border-bottom: none; }
.id { font-weight: 600; }
.stage-title { display: block; color: var(--muted); font-size: .9rem; }
.points { white-space: nowrap; font-variant-numeric: tabular-nums; width: 13rem; }
.points .number { display: inline-block; min-width: 4.5rem; }
.bar { display: inline-block; width: 6rem; height: .6rem; background: #eaeef2; border-radius: .3rem;
       margin-left: .7rem; vertical-align: middle; overflow: hidden; }
.bar > span { display: block; height: 100%; background: var(--ok); }
.failed .bar > span { background: #d4a72c; }
.passed .status { color: var(--ok); }
.failed .status { color: var(--bad); }
.not-attempted .status { color: var(--none); }
.next { background: var(--soft); border-radius: 6px; padding: 8px 12px; }
section.stage { border-top: 3px solid var(--line); margin-top: 36px; padding-top: 6px; }
section.stage.passed { border-top-color: var(--ok); }
section.stage.failed { border-top-color: var(--bad); }
h2 { font-size: 1.3rem; margin: 6px 0 2px; display: flex; gap: 12px; align-items: baseline; flex-wrap: wrap; }
h2 .score { margin-left: auto; font-variant-numeric: tabular-nums; }
h3 { font-size: 1.05rem; margin: 18px 0 6px; }
.meta { margin: 0; color: var(--muted); }
article.test { border: 1px solid var(--line); border-left: 4px solid var(--bad); border-radius: 6px;
               padding: 10px 14px; margin: 12px 0; }
article.test.passed { border-left-color: var(--ok); }
article.test.lost { border-left-color: var(--lost); }
article.test.not-attempted { border-left-color: var(--none); }
h4 { margin: 0 0 6px; font-size: 1rem; }
.label { font-size: .8rem; font-weight: 700; padding: 1px 7px; border-radius: 4px; color: #fff;
         background: var(--bad); margin-right: 8px; }
.passed .label { background: var(--ok); }
.lost .label { background: var(--lost); }
.not-attempted .label { background: var(--none); }
.test-points { color: var(--muted); font-weight: 400; }
pre { white-space: pre-wrap; overflow-wrap: anywhere; font-size: 14px; line-height: 1.45; background: var(--soft);
      padding: 8px 10px; border-radius: 4px; margin: 6px 0; }
.hint { background: #fff8c5; border: 1px solid #d4a72c; padding: 7px 10px; border-radius: 4px; margin: 6px 0; }
.note { color: var(--muted); font-size: .93rem; margin: 4px 0; }
details.trace { margin: 10px 0; }
details.trace summary { cursor: pointer; font-weight: 600; color: inherit; }
/* A long trace (a path's) scrolls in its own box, which opens at its first disagreement. */
.trace-steps { position: relative; max-height: 28rem; overflow-y: auto; border: 1px solid var(--line); margin: 6px 0; }
table.trace { border-collapse: collapse; font-family: ui-monospace, monospace; font-size: .82rem; }
table.trace thead th { position: sticky; top: 0; background: #fff; }
table.trace td:first-child { white-space: nowrap; }
table.trace th, table.trace td { text-align: left; vertical-align: top; padding: 3px 8px;
  border-bottom: 1px solid var(--line); overflow-wrap: anywhere; }
table.trace tr.agrees td { color: var(--muted); }
table.trace tr.first td { background: #ffebe9; color: inherit; }
table.trace .mark { color: #cf222e; font-weight: 600; }
.row { display: flex; flex-wrap: wrap; gap: 14px; margin: 10px 0 0; }
.row figure { margin: 0; }
.row img { display: block; max-width: 100%; outline: 1px solid var(--line); }
figcaption { font-size: .9rem; color: var(--muted); max-width: 320px; }
.comparison { margin: 14px 0 4px; }
.compare { position: relative; display: inline-block; width: 640px; max-width: 100%; cursor: ew-resize;
           user-select: none; touch-action: none; }
.compare img { display: block; width: 100%; image-rendering: pixelated; }
.compare img.over { position: absolute; left: 0; top: 0; clip-path: inset(0 calc(100% - var(--split)) 0 0); }
.compare .line { position: absolute; top: 0; bottom: 0; left: var(--split); width: 2px; margin-left: -1px;
                 background: #fff; box-shadow: 0 0 0 1px rgba(0, 0, 0, .45); pointer-events: none; }
.comparison input { display: block; width: 640px; max-width: 100%; margin: 6px 0 0; }
.comparison p { margin: 0; font-size: .9rem; color: var(--muted); }
details { margin: 10px 0; }
summary { cursor: pointer; color: var(--ok); }
details ul { margin: 6px 0; }
.warning { border: 2px solid var(--bad); border-radius: 6px; padding: 8px 12px; margin: 0 0 16px; }
footer { color: var(--muted); font-size: .9rem; margin-top: 40px; border-top: 1px solid var(--line); padding-top: 8px; }
)css";

// The sliders, and after loading: a warning naming any picture that cannot be shown, and what a
// checker reads (tests/report/): <pre id="report-check"> gets the pictures loaded, the table's rows
// and where the table and each picture are on the page.
constexpr const char* kScript = R"js(
(function () {
  document.querySelectorAll('.comparison').forEach(function (comparison) {
    var box = comparison.querySelector('.compare'), slider = comparison.querySelector('input');
    function set(percent) { box.style.setProperty('--split', percent + '%'); slider.value = percent; }
    function drag(event) {
      if (event.type === 'pointermove' && !(event.buttons & 1)) return;
      var r = box.getBoundingClientRect();
      set(Math.round(Math.max(0, Math.min(1, (event.clientX - r.left) / r.width)) * 1000) / 10);
    }
    slider.addEventListener('input', function () { set(slider.value); });
    box.addEventListener('pointerdown', drag);
    box.addEventListener('pointermove', drag);
  });
  function where(element) {
    var r = element.getBoundingClientRect();
    return [r.left + window.scrollX, r.top + window.scrollY, r.width, r.height];
  }
  window.addEventListener('load', function () {
    document.querySelectorAll('.trace-steps').forEach(function (box) {
      var first = box.querySelector('tr.first');
      if (first) box.scrollTop = Math.max(0, first.offsetTop - box.clientHeight / 3);
    });
    var images = Array.prototype.slice.call(document.images);
    var missing = images.filter(function (image) { return !(image.complete && image.naturalWidth > 0); });
    if (missing.length > 0) {
      var warning = document.getElementById('images-missing'), list = warning.querySelector('ul'), listed = {};
      missing.forEach(function (image) {
        var name = image.getAttribute('src');
        if (listed[name]) return;
        listed[name] = true;
        var item = document.createElement('li');
        item.textContent = name;
        list.appendChild(item);
      });
      warning.hidden = false;
    }
    var table = document.querySelector('table.scores');
    document.getElementById('report-check').textContent = JSON.stringify({
      images: images.length,
      loaded: images.length - missing.length,
      rows: table.tBodies[0].rows.length,
      table: where(table),
      pictures: Array.prototype.map.call(document.querySelectorAll('img.picture'), function (image) {
        return { src: image.getAttribute('src'), natural: [image.naturalWidth, image.naturalHeight], at: where(image) };
      }),
      height: document.documentElement.scrollHeight
    });
  });
})();
)js";

std::string text_of(const Message& message, Language language) { return render(message, language); }

// A relative path or file name as a URL: every byte but letters, digits and -._~/ percent-encoded
// (and ':' too unless `keep_colon`: in a relative URL it would start a scheme).
std::string url_of(const std::string& path, bool keep_colon = false) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string url;
  for (const char c : path) {
    const unsigned char b = static_cast<unsigned char>(c);
    if (std::isalnum(b) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/' || (keep_colon && c == ':')) {
      url += c;
    } else {
      url += '%';
      url += kHex[b >> 4];
      url += kHex[b & 15];
    }
  }
  return url;
}

// Escaped text with every handout path of the kit (docs/01_camera_rays.md, docs/zh/...) a link.
std::string with_handout_links(const std::string& text, const std::string& kit_href) {
  static const std::regex handout("docs/(zh/)?[A-Za-z0-9_-]+\\.md");
  const std::string escaped = escape_html(text);
  std::string out;
  std::size_t done = 0;
  for (std::sregex_iterator it(escaped.begin(), escaped.end(), handout), end; it != end; ++it) {
    const std::string path = it->str();
    out += escaped.substr(done, static_cast<std::size_t>(it->position()) - done);
    if (std::filesystem::exists(std::filesystem::path(kit_source_folder()) / path))
      out += "<a href=\"" + escape_html(kit_href + "/" + path) + "\">" + path + "</a>";
    else
      out += path;
    done = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + escaped.substr(done);
}

const char* status_class(const StageResult& stage) {
  if (stage.not_attempted) return "not-attempted";
  return stage.earned() == stage.max() && !stage.problem ? "passed" : "failed";
}

const char* test_class(Status status) {
  switch (status) {
    case Status::Passed: return "passed";
    case Status::Failed: return "failed";
    case Status::NotAttempted: return "not-attempted";
    case Status::Lost: break;
  }
  return "lost";
}

MessageId test_label(Status status) {
  switch (status) {
    case Status::Passed: return MessageId::console_label_passed;
    case Status::Failed: return MessageId::console_label_failed;
    case Status::NotAttempted: return MessageId::console_label_not_attempted;
    case Status::Lost: break;
  }
  return MessageId::console_label_lost;
}

std::string points_cell(int earned, int max) {
  const int percent = max > 0 ? 100 * earned / max : 0;
  return "<td class=\"points\"><span class=\"number\">" + std::to_string(earned) + "/" + std::to_string(max) +
         "</span><span class=\"bar\"><span style=\"width:" + std::to_string(percent) + "%\"></span></span></td>";
}

std::string figure(const std::string& file, const std::string& caption) {
  return "<figure><img class=\"picture\" src=\"" + escape_html(url_of(file)) + "\" alt=\"" + caption + "\"><figcaption>" +
         caption + "</figcaption></figure>";
}

// A failing picture's pixel traced through the stage code (raylab/trace.h): one row per step, the
// first disagreement marked with its function and file. Every text is the stage server's, escaped.
std::string trace_html(const PixelTrace& trace, const std::string& command, Language language) {
  std::string html = "<details class=\"trace\" open><summary>" +
                     escape_html(text_of(trace.settings.integrator == IntegratorKind::Whitted
                                             ? Message{MessageId::report_trace_heading,
                                                       {{"x", std::to_string(trace.x)}, {"y", std::to_string(trace.y)}}}
                                             : Message{MessageId::report_trace_heading_sample,
                                                       {{"x", std::to_string(trace.x)},
                                                        {"y", std::to_string(trace.y)},
                                                        {"sample", std::to_string(trace.settings.sample)}}},
                                         language)) +
                     "</summary>\n<div class=\"trace-steps\"><table class=\"trace\"><thead><tr><th>#</th><th>" +
                     escape_html(text_of(MessageId::report_trace_call, language)) + "</th><th>" +
                     escape_html(text_of(MessageId::report_yours, language)) + "</th><th>" +
                     escape_html(text_of(MessageId::report_trace_contract, language)) + "</th></tr></thead><tbody>\n";
  const int first = trace.first_disagreement();
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const TraceStep& step = trace.steps[i];
    const bool is_first = static_cast<int>(i) == first;
    std::string call = escape_html((step.stage.empty() ? "" : step.stage + "  ") + step.call);
    if (!step.note.empty()) call += "<br>" + escape_html(step.note);
    if (is_first) {
      const std::string file = step.file();
      const std::string mark =
          step.function.empty()
              ? text_of(MessageId::report_trace_first, language)
              : text_of({MessageId::report_trace_first_at,
                         {{"function", step.function}, {"file", file.empty() ? step.stage : file}}},
                        language);
      call += "<br><span class=\"mark\">" + escape_html(mark) + "</span>";
    }
    html += std::string("<tr class=\"") + (is_first ? "first" : step.agrees ? "agrees" : "differs") + "\"><td>" +
            std::to_string(i + 1) + "</td><td>" + call + "</td><td>" + escape_html(step.yours) + "</td><td>" +
            escape_html(step.expected) + "</td></tr>\n";
  }
  html += "</tbody></table></div>\n<p class=\"note\">" +
          escape_html(text_of({MessageId::report_trace_command, {{"command", command}}}, language)) + "</p></details>\n";
  return html;
}

// yours | reference | difference, then the slider: yours over the reference, cut at the line.
std::string pictures_html(const ImageComparison& images, Language language) {
  const std::string yours = escape_html(text_of(images.yours_label, language));
  const std::string reference = escape_html(text_of(images.reference_label, language));
  std::string html = "<div class=\"row\">" + figure(images.yours, yours) + figure(images.reference, reference);
  if (!images.difference.empty())
    html += figure(images.difference, escape_html(text_of(images.difference_label, language)));
  html += "</div>\n";
  const std::string slider_text =
      escape_html(text_of({MessageId::report_slider, {{"yours", images.yours_label}, {"reference", images.reference_label}}},
                          language));
  html += "<div class=\"comparison\"><div class=\"compare\" style=\"--split:50%\">"
          "<img class=\"under\" src=\"" + escape_html(url_of(images.reference)) + "\" alt=\"" + reference + "\">"
          "<img class=\"over\" src=\"" + escape_html(url_of(images.yours)) + "\" alt=\"" + yours + "\">"
          "<div class=\"line\"></div></div>"
          "<input type=\"range\" min=\"0\" max=\"100\" step=\"0.1\" value=\"50\" aria-label=\"" + slider_text + "\">"
          "<p>" + slider_text + "</p></div>\n";
  if (images.worst_pixel) html += trace_html(*images.worst_pixel, images.trace_command, language);
  return html;
}

std::string test_html(const TestResult& test, Language language, const std::string& kit_href) {
  std::string html = std::string("<article class=\"test ") + test_class(test.status) + "\"><h4><span class=\"label\">" +
                     escape_html(text_of(test_label(test.status), language)) + "</span>" + escape_html(test.info.name) +
                     "<span class=\"test-points\">" +
                     escape_html(text_of({test.info.points == 1 ? MessageId::console_test_point : MessageId::console_test_points, {{"points", std::to_string(test.info.points)}}},
                                         language)) +
                     "</span></h4>\n";
  for (const Message& message : test.messages)
    html += "<pre>" + with_handout_links(text_of(message, language), kit_href) + "</pre>\n";
  for (const Message& hint : test.hints)
    html += "<p class=\"hint\">" +
            with_handout_links(text_of({MessageId::console_hint, {{"hint", hint}}}, language), kit_href) + "</p>\n";
  for (const Message& note : test.notes)
    html += "<p class=\"note\">" + with_handout_links(text_of(note, language), kit_href) + "</p>\n";
  for (const ImageComparison& images : test.images) html += pictures_html(images, language);
  return html + "</article>\n";
}

std::string stage_html(const StageResult& stage, Language language, const std::string& kit_href) {
  const StageInfo& info = *stage.stage;
  const std::string& handout_file = language == Language::Chinese ? info.handout_file_zh : info.handout_file;
  std::string html = std::string("<section class=\"stage ") + status_class(stage) + "\" id=\"stage-" +
                     escape_html(info.id) + "\">\n<h2><span class=\"id\">" + escape_html(info.id) + "</span><span>" +
                     escape_html(text_of(info.title_text, language)) + "</span><span class=\"score\">" +
                     std::to_string(stage.earned()) + "/" + std::to_string(stage.max()) + "</span></h2>\n";
  // "handout: docs/05_bvh.md, section 5" with the file a link.
  std::string handout = escape_html(text_of(info.handout_text, language));
  const std::string shown = escape_html(handout_file);
  const std::size_t at = handout.find(shown);
  if (at != std::string::npos && std::filesystem::exists(std::filesystem::path(kit_source_folder()) / handout_file))
    handout.replace(at, shown.size(), "<a href=\"" + escape_html(kit_href + "/" + handout_file) + "\">" + shown + "</a>");
  const std::string marker = "@HANDOUT@";
  std::string line = escape_html(text_of({MessageId::report_handout, {{"handout", marker}}}, language));
  line.replace(line.find(marker), marker.size(), handout);
  html += "<p class=\"meta\">" + line + "</p>\n<p class=\"meta status\">" + escape_html(stage_status(stage)) + "</p>\n";

  if (stage.not_attempted) {
    if (!stage.tests.empty() && !stage.tests.front().messages.empty())
      html += "<pre>" + with_handout_links(text_of(stage.tests.front().messages.front(), language), kit_href) + "</pre>\n";
  } else {
    // The tests that lost points, and every test with pictures; the others in one line that opens.
    std::string failed, shown_passed, passed_list;
    int passed = 0;
    for (const TestResult& test : stage.tests) {
      if (test.status != Status::Passed) {
        failed += test_html(test, language, kit_href);
        continue;
      }
      ++passed;
      if (!test.images.empty()) shown_passed += test_html(test, language, kit_href);
      passed_list += "<li>" + escape_html(test.info.name) + "<span class=\"test-points\">" +
                     escape_html(text_of({test.info.points == 1 ? MessageId::console_test_point : MessageId::console_test_points, {{"points", std::to_string(test.info.points)}}},
                                         language)) +
                     "</span>";
      for (const Message& hint : test.hints)  // advice that cost no points
        passed_list += "<p class=\"hint\">" +
                       with_handout_links(text_of({MessageId::console_hint, {{"hint", hint}}}, language), kit_href) + "</p>";
      for (const Message& note : test.notes)
        passed_list += "<p class=\"note\">" + with_handout_links(text_of(note, language), kit_href) + "</p>";
      passed_list += "</li>\n";
    }
    if (!failed.empty()) html += "<h3>" + escape_html(text_of(MessageId::report_failures, language)) + "</h3>\n" + failed;
    if (!shown_passed.empty())
      html += "<h3>" + escape_html(text_of(MessageId::report_passed_pictures, language)) + "</h3>\n" + shown_passed;
    if (passed > 0)
      html += "<details><summary>" +
              escape_html(text_of({MessageId::report_passed_tests, {{"count", std::to_string(passed)}}}, language)) +
              "</summary><ul>\n" + passed_list + "</ul></details>\n";
  }
  if (!stage.output.empty()) {
    html += "<h3>" + escape_html(text_of(MessageId::console_output_header, language)) + "</h3>\n<pre class=\"output\">" +
            escape_html(stage.output.substr(0, kShownOutputBytes)) + "</pre>\n";
    if (stage.output.size() > kShownOutputBytes)
      html += "<p class=\"note\">" +
              escape_html(text_of({MessageId::console_output_cut, {{"bytes", std::to_string(stage.output.size())}}},
                                  language)) +
              "</p>\n";
  }
  return html + "</section>\n";
}

}  // namespace

std::string escape_html(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const std::size_t length = utf8_length(text, i);
      out += length > 0 ? shown_as_text(std::string_view(text).substr(i, length)) : std::string("\xEF\xBF\xBD");
      i += length > 0 ? length : 1;
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += (c < 32 && c != '\n' && c != '\t') || c == 127 ? '?' : static_cast<char>(c);
    }
    ++i;
  }
  return out;
}

std::string report_html(const std::vector<StageResult>& results, const Message& description, Language language,
                        const std::string& kit_href) {
  int earned = 0, max = 0;
  for (const StageResult& stage : results) {
    earned += stage.earned();
    max += stage.max();
  }
  const Message title{MessageId::console_title, {{"description", description}}};
  std::string html = std::string("<!DOCTYPE html>\n<html lang=\"") + (language == Language::Chinese ? "zh-CN" : "en") +
                     "\">\n<head>\n<meta charset=\"utf-8\">\n"
                     "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
                     // Nothing from anywhere but this folder, even if a text slipped through unescaped.
                     "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src 'self'; "
                     "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n<title>" +
                     escape_html(text_of({MessageId::report_page_title,
                                          {{"earned", std::to_string(earned)}, {"max", std::to_string(max)}, {"title", title}}},
                                         language)) +
                     "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<main>\n";
  html += "<h1>" + escape_html(text_of(title, language)) + "</h1>\n<p class=\"total\">" +
          escape_html(text_of(MessageId::console_total, language)) + " <strong>" + std::to_string(earned) + "/" +
          std::to_string(max) + "</strong></p>\n";
  html += "<div class=\"warning\" id=\"images-missing\" hidden><p>" +
          escape_html(text_of(MessageId::report_images_missing, language)) + "</p><ul></ul></div>\n";

  html += "<table class=\"scores\">\n<thead><tr><th>" + escape_html(text_of(MessageId::console_stage, language)) +
          "</th><th>" + escape_html(text_of(MessageId::console_points, language)) + "</th><th>" +
          escape_html(text_of(MessageId::console_status, language)) + "</th></tr></thead>\n<tbody>\n";
  for (const StageResult& stage : results) {
    const std::string id = escape_html(stage.stage->id);
    html += std::string("<tr class=\"") + status_class(stage) + "\" data-stage=\"" + id + "\" data-points=\"" +
            std::to_string(stage.earned()) + "/" + std::to_string(stage.max()) + "\"><td><a class=\"id\" href=\"#stage-" +
            id + "\">" + id + "</a><span class=\"stage-title\">" + escape_html(text_of(stage.stage->title_text, language)) +
            "</span></td>" + points_cell(stage.earned(), stage.max()) + "<td class=\"status\">" +
            escape_html(stage_status(stage)) + "</td></tr>\n";
  }
  html += "</tbody>\n<tfoot><tr><th>" + escape_html(text_of(MessageId::console_total, language)) + "</th>" +
          points_cell(earned, max) + "<td></td></tr></tfoot>\n</table>\n";
  if (const Message* next = next_step(results))
    html += "<p class=\"next\">" +
            with_handout_links(text_of({MessageId::console_next, {{"what", *next}}}, language), kit_href) + "</p>\n";

  for (const StageResult& stage : results) html += stage_html(stage, language, kit_href);
  html += "<footer>" + escape_html(text_of(MessageId::report_footer, language)) + "</footer>\n</main>\n";
  html += "<pre id=\"report-check\" hidden></pre>\n<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";
  return html;
}

std::string write_report_html(const std::vector<StageResult>& results, const Message& description,
                              const std::string& directory) {
  // Links to the handouts relative to the page, so that they work wherever the kit is (also in
  // the student release), unless the page is on another drive than the kit (Windows).
  std::error_code error;
  const std::filesystem::path page_folder = std::filesystem::weakly_canonical(std::filesystem::absolute(directory), error);
  const std::filesystem::path kit = std::filesystem::weakly_canonical(std::filesystem::path(kit_source_folder()), error);
  const std::string relative = kit.lexically_relative(page_folder).generic_string();
  const std::string absolute = kit.generic_string();
  const std::string kit_href = !relative.empty() ? url_of(relative)
                                                 : "file://" + std::string(absolute.rfind('/', 0) == 0 ? "" : "/") +
                                                       url_of(absolute, true);
  const std::string path = (std::filesystem::path(directory) / "index.html").string();
  replace_file(path, report_html(results, description, language(), kit_href));
  return path;
}

}  // namespace raylab::grading
