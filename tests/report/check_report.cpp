// Checks a grading run's HTML report as headless Chromium showed it (check_report.sh runs the
// grader and the browser):
//   - the page needs nothing from the network: no URL with a scheme but file:, nothing from //host,
//     no CSS url(), and a Content-Security-Policy; it is in the run's language;
//   - after loading, its script ran and every image loaded (naturalWidth > 0: the marker
//     <pre id="report-check"> the page writes), and the table has a row per stage with
//     results.json's points, and the total;
//   - every picture the grader wrote for the report (*-yours.png, -reference.png, -difference.png,
//     -intended.png) is on the page, and each is really on the screenshot where the page put it,
//     at its own size (compared with its file); the table's area of the screenshot holds text;
//   - --expect TEXT is in the DOM, --forbid TEXT is not (student output shown as text only).
//
//   raylab_report_check --html index.html --dom dom.html --results results.json --screenshot page.png
//                       --lang en|zh --pictures none|some [--expect TEXT]... [--forbid TEXT]...
#include "raylab/image.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> problems;
void problem(const std::string& text) { problems.push_back(text); }

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string unescape_html(std::string text) {
  for (const auto& [entity, character] : std::vector<std::pair<std::string, std::string>>{
           {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&nbsp;", " "}, {"&amp;", "&"}}) {
    for (std::size_t at = text.find(entity); at != std::string::npos; at = text.find(entity, at + character.size()))
      text.replace(at, entity.size(), character);
  }
  return text;
}

// Needs nothing from the network, and speaks the run's language.
void check_page_source(const std::string& html, const std::string& language) {
  const std::string lang = language == "zh" ? "zh-CN" : "en";
  if (html.find("<html lang=\"" + lang + "\">") == std::string::npos) problem("index.html is not marked lang=\"" + lang + "\"");
  if (html.find("Content-Security-Policy") == std::string::npos) problem("index.html has no Content-Security-Policy");
  if (html.find("url(") != std::string::npos) problem("index.html's style loads something with url(...)");
  const std::regex link("(src|href|action|data)=\"([^\"]*)\"");
  int links = 0;
  for (std::sregex_iterator it(html.begin(), html.end(), link), end; it != end; ++it, ++links) {
    const std::string url = unescape_html((*it)[2]);
    std::smatch scheme;
    if (url.rfind("//", 0) == 0 || (std::regex_search(url, scheme, std::regex("^[A-Za-z][A-Za-z0-9+.-]*:")) &&
                                    scheme.str() != "file:"))
      problem("index.html links to the network: " + url);
  }
  if (links == 0) problem("index.html has no link or image at all");
}

struct Rect {
  double x = 0, y = 0, width = 0, height = 0;
};
Rect rect_of(const nlohmann::json& at) { return {at.at(0), at.at(1), at.at(2), at.at(3)}; }

// Mean absolute difference per channel between `picture` and the screenshot's pixels at (x, y).
double difference_at(const raylab::Image& screenshot, const raylab::Image& picture, int x0, int y0) {
  double sum = 0.0;
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x) {
      const glm::vec3 d = glm::abs(screenshot.at(x0 + x, y0 + y) - picture.at(x, y));
      sum += d.x + d.y + d.z;
    }
  return sum / (3.0 * picture.width() * picture.height());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Checks a grading run's HTML report as headless Chromium showed it"};
  std::string html_path, dom_path, results_path, screenshot_path, language = "en", pictures = "some";
  std::vector<std::string> expected_texts, forbidden_texts;
  app.add_option("--html", html_path, "The report: <output>/index.html")->required()->check(CLI::ExistingFile);
  app.add_option("--dom", dom_path, "Chromium's --dump-dom of it")->required()->check(CLI::ExistingFile);
  app.add_option("--results", results_path, "The same run's results.json")->required()->check(CLI::ExistingFile);
  app.add_option("--screenshot", screenshot_path, "Chromium's --screenshot of the whole page")->required();
  app.add_option("--lang", language, "The run's language")->check(CLI::IsMember({"en", "zh"}));
  app.add_option("--pictures", pictures, "Whether the run wrote pictures")->check(CLI::IsMember({"none", "some"}));
  app.add_option("--expect", expected_texts, "A text the DOM must hold");
  app.add_option("--forbid", forbidden_texts, "A text the DOM must not hold");
  CLI11_PARSE(app, argc, argv);

  try {
    const std::string html = read_text(html_path), dom = read_text(dom_path);
    const std::filesystem::path folder = std::filesystem::path(html_path).parent_path();
    check_page_source(html, language);

    // What the page's script found after loading.
    const std::string marker_start = "<pre id=\"report-check\" hidden=\"\">";
    const std::size_t start = dom.find(marker_start);
    const std::size_t end = start == std::string::npos ? start : dom.find("</pre>", start);
    const std::string marker_text =
        end == std::string::npos ? "" : unescape_html(dom.substr(start + marker_start.size(), end - start - marker_start.size()));
    if (marker_text.empty()) {
      std::printf("FAIL: the page's script did not write its marker (<pre id=\"report-check\">): did it run?\n");
      return 1;
    }
    const nlohmann::json marker = nlohmann::json::parse(marker_text);
    const int images = marker.at("images"), loaded = marker.at("loaded");
    if (loaded != images) problem(std::to_string(images - loaded) + " of " + std::to_string(images) + " images did not load");

    // The table against results.json: a row per stage with its points, and the total.
    const nlohmann::json results = nlohmann::json::parse(read_text(results_path));
    std::map<std::string, std::pair<int, int>> stages;
    std::vector<std::string> order;
    for (const nlohmann::json& test : results.at("tests")) {
      const std::string name = test.at("name");
      const std::string stage = name.substr(0, name.find(':'));
      if (!stages.count(stage)) order.push_back(stage);
      stages[stage].first += test.at("score").get<int>();
      stages[stage].second += test.at("max_score").get<int>();
    }
    if (marker.at("rows").get<std::size_t>() != stages.size())
      problem("the table has " + marker.at("rows").dump() + " rows; results.json has " + std::to_string(stages.size()) +
              " stages");
    for (const std::string& stage : order) {
      const std::string row = "data-stage=\"" + stage + "\" data-points=\"" + std::to_string(stages[stage].first) + "/" +
                              std::to_string(stages[stage].second) + "\"";
      if (dom.find(row) == std::string::npos) problem("no table row " + row);
    }
    const std::string total = "<strong>" + results.at("score").dump() + "/" + results.at("max_score").dump() + "</strong>";
    if (dom.find(total) == std::string::npos) problem("the page does not show the total " + total);
    for (const std::string& text : expected_texts)
      if (dom.find(text) == std::string::npos) problem("the page does not hold \"" + text + "\"");
    for (const std::string& text : forbidden_texts)
      if (dom.find(text) != std::string::npos) problem("the page holds \"" + text + "\"");

    // Every picture the grader wrote for the report is on the page, and on the screenshot.
    std::set<std::string> written, shown;
    for (const auto& file : std::filesystem::directory_iterator(folder)) {
      const std::string name = file.path().filename().string();
      for (const char* ending : {"-yours.png", "-reference.png", "-difference.png", "-intended.png"})
        if (name.size() > std::string(ending).size() && name.compare(name.size() - std::string(ending).size(), std::string::npos, ending) == 0)
          written.insert(name);
    }
    const raylab::Image screenshot = raylab::read_image(screenshot_path);
    double worst = 0.0;
    for (const nlohmann::json& picture : marker.at("pictures")) {
      const std::string src = picture.at("src");
      shown.insert(src);
      const Rect at = rect_of(picture.at("at"));
      if (!std::filesystem::exists(folder / src)) {
        problem(src + " is on the page but not in " + folder.string());
        continue;
      }
      const raylab::Image image = raylab::read_image((folder / src).string());
      if (picture.at("natural") != nlohmann::json::array({image.width(), image.height()}) ||
          std::lround(at.width) != image.width() || std::lround(at.height) != image.height()) {
        problem(src + " is shown at " + picture.at("at").dump() + ", not at its own size " + std::to_string(image.width()) +
                "x" + std::to_string(image.height()));
        continue;
      }
      // Where the page put it, give or take a pixel of rounding.
      double best = 1e9;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int x0 = static_cast<int>(std::lround(at.x)) + dx, y0 = static_cast<int>(std::lround(at.y)) + dy;
          if (x0 < 0 || y0 < 0 || x0 + image.width() > screenshot.width() || y0 + image.height() > screenshot.height()) continue;
          best = std::min(best, difference_at(screenshot, image, x0, y0));
        }
      if (best > 0.02)
        problem(src + " is not on the screenshot where the page put it (" + picture.at("at").dump() +
                (best > 1e8 ? "): outside the screenshot" : "): mean difference " + std::to_string(best)));
      else
        worst = std::max(worst, best);
    }
    for (const std::string& name : written)
      if (!shown.count(name)) problem("the grader wrote " + name + " but the page does not show it");
    if (pictures == "none" && !written.empty()) problem("this run should write no pictures, but wrote " + *written.begin());
    if (pictures == "some" && shown.empty()) problem("the page shows no pictures");

    // The table's area holds text and bars: pixels that are not the white page.
    const Rect table = rect_of(marker.at("table"));
    long long inked = 0, area = 0;
    for (int y = std::max(0, static_cast<int>(table.y)); y < std::min<int>(screenshot.height(), table.y + table.height); ++y)
      for (int x = std::max(0, static_cast<int>(table.x)); x < std::min<int>(screenshot.width(), table.x + table.width); ++x) {
        ++area;
        const glm::vec3 p = screenshot.at(x, y);
        inked += std::min({p.x, p.y, p.z}) < 0.6f;
      }
    if (area == 0 || inked < area / 100)
      problem("the score table's area of the screenshot is blank (" + std::to_string(inked) + " of " + std::to_string(area) +
              " pixels not white)");

    if (!problems.empty()) {
      for (const std::string& p : problems) std::printf("FAIL: %s\n", p.c_str());
      return 1;
    }
    std::printf("report checked (%s): %zu table rows match results.json, %d of %d images loaded, %zu pictures on the "
                "screenshot where the page put them (largest mean difference %.4f), table area %.1f%% ink\n",
                language.c_str(), stages.size(), loaded, images, shown.size(), worst,
                area > 0 ? 100.0 * static_cast<double>(inked) / static_cast<double>(area) : 0.0);
    return 0;
  } catch (const std::exception& e) {
    std::printf("FAIL: %s\n", e.what());
    return 1;
  }
}
