// The autograder's catalogue (autograder/runner/messages.def and the stages' own,
// autograder/suites/<id>_messages.def): every message in English and
// Simplified Chinese with the same placeholders and the twin handout's sections, every stage
// title in both languages, and no hint that bypasses the catalogue. The ctest messages_are_paired.
#include "messages.h"
#include "bvh_violation_text.h"

#include "raylab/stage_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace raylab::grading {
namespace {

void set_variable(const char* name, const char* value) {
#ifdef _WIN32
  _putenv_s(name, value);
#else
  ::setenv(name, value, 1);
#endif
}
void unset_variable(const char* name) {
#ifdef _WIN32
  _putenv_s(name, "");
#else
  ::unsetenv(name);
#endif
}

const char* const kWhere = "autograder/runner/messages.def or autograder/suites/<id>_messages.def";

// Whether a UTF-8 text holds a CJK ideograph (U+4E00..U+9FFF: E4 B8 80 .. E9 BF BF).
bool has_chinese(std::string_view text) {
  for (std::size_t i = 0; i + 2 < text.size(); ++i) {
    const unsigned char lead = static_cast<unsigned char>(text[i]);
    if (lead >= 0xE4 && lead <= 0xE9) return true;
  }
  return false;
}

// The text without its placeholders: does it say anything in words (two letters or more in a row,
// not a name of code such as t_hit)? "t = {t}" does not.
bool has_words(std::string_view text) {
  std::string without = std::regex_replace(std::string(text), std::regex("\\{[A-Za-z0-9_]+\\}"), "");
  without = std::regex_replace(without, std::regex("[A-Za-z0-9]*_[A-Za-z0-9_]*"), "");
  return std::regex_search(without, std::regex("[A-Za-z]{2}"));
}

std::multiset<std::string> placeholder_set(std::string_view text) {
  const std::vector<std::string> names = placeholders_of(text);
  return {names.begin(), names.end()};
}

TEST(Messages, EveryMessageHasItsChineseText) {
  for (const CatalogueEntry& entry : message_catalogue()) {
    EXPECT_FALSE(entry.english.empty()) << kWhere << ": " << entry.name << " has no English text";
    if (has_words(entry.english)) {
      EXPECT_TRUE(has_chinese(entry.chinese))
          << kWhere << ": " << entry.name << " has no Chinese text (\"" << entry.chinese << "\"): write it as the third "
          << "argument of RAYLAB_MESSAGE(" << entry.name << ", \"English\", \"简体中文\"), in the terms of docs/glossary.md";
    }
  }
}

TEST(Messages, BothTextsHaveTheSamePlaceholders) {
  for (const CatalogueEntry& entry : message_catalogue())
    EXPECT_EQ(placeholder_set(entry.english), placeholder_set(entry.chinese))
        << kWhere << ": " << entry.name << ": the English and the Chinese text must use the same {placeholders}";
}

TEST(Messages, ChineseHintsCiteTheChineseHandoutAndTheSameSection) {
  const std::regex handout("docs/([A-Za-z0-9_.-]+\\.md)"), section("section ([0-9]+)"), chinese_section("第 ([0-9]+) 节");
  for (const CatalogueEntry& entry : message_catalogue()) {
    const std::string english(entry.english), chinese(entry.chinese);
    for (std::sregex_iterator it(english.begin(), english.end(), handout), end; it != end; ++it)
      EXPECT_NE(chinese.find("docs/zh/" + (*it)[1].str()), std::string::npos)
          << kWhere << ": " << entry.name << " cites " << (*it)[0] << " in English: the Chinese text cites docs/zh/"
          << (*it)[1];
    std::vector<std::string> english_sections, chinese_sections;
    for (std::sregex_iterator it(english.begin(), english.end(), section), end; it != end; ++it)
      english_sections.push_back((*it)[1]);
    for (std::sregex_iterator it(chinese.begin(), chinese.end(), chinese_section), end; it != end; ++it)
      chinese_sections.push_back((*it)[1]);
    EXPECT_EQ(english_sections, chinese_sections)
        << kWhere << ": " << entry.name << ": \"section N\" in English is \"第 N 节\" in Chinese";
  }
}

TEST(Messages, EveryStageHasAChineseTitle) {
  for (const StageDescription& stage : stage_table())
    EXPECT_TRUE(has_chinese(stage.title_zh)) << "stages.json: the stage " << stage.id << " has no \"title_zh\": add "
                                             << "\"title_zh\": \"<its title in Simplified Chinese>\" after \"title\"";
}

// Every hint, note and failure text is a catalogue entry: the suites never wrap a text of their
// own in verbatim() (nor the English-only untranslated() that once was), nor stream a text into an
// assertion (ADD_FAILURE() << "...", EXPECT_EQ(...) << "..."), which --lang zh would show in
// English. No exception: a suite that builds a value's text (a point, a replayable input) joins
// strings instead of streaming literals, so that any << "..." in a suite is a failure text.
// The GoogleTest assertions of a suite's source (EXPECT_..., ASSERT_..., ADD_FAILURE(), FAIL())
// whose message is not exactly one failure_text(...): with no message GoogleTest words the failure
// in English ("Expected equality of these values"), and a text streamed in is the suite's own.
// Each as "<line>: <the assertion's start>". Comments and string literals are skipped.
std::vector<std::string> assertions_without_catalogue_text(const std::string& source) {
  std::vector<std::string> found;
  // Index past a string or character literal starting at `i`, or past a comment; `i` if neither.
  auto skip = [&](std::size_t i) {
    if (source.compare(i, 2, "//") == 0) {
      const std::size_t end = source.find('\n', i);
      return end == std::string::npos ? source.size() : end;
    }
    if (source.compare(i, 2, "/*") == 0) {
      const std::size_t end = source.find("*/", i + 2);
      return end == std::string::npos ? source.size() : end + 2;
    }
    if (source.compare(i, 3, "R\"(") == 0) {
      const std::size_t end = source.find(")\"", i + 3);
      return end == std::string::npos ? source.size() : end + 2;
    }
    if (source[i] == '"' || (source[i] == '\'' && (i == 0 || !std::isalnum(static_cast<unsigned char>(source[i - 1]))))) {
      const char quote = source[i];
      for (std::size_t j = i + 1; j < source.size(); ++j) {
        if (source[j] == '\\') ++j;
        else if (source[j] == quote) return j + 1;
      }
      return source.size();
    }
    return i;
  };
  // Index just past the parenthesis that closes the one at `open`.
  auto close = [&](std::size_t open) {
    int depth = 0;
    for (std::size_t i = open; i < source.size();) {
      const std::size_t after = skip(i);
      if (after != i) {
        i = after;
        continue;
      }
      if (source[i] == '(') ++depth;
      if (source[i] == ')' && --depth == 0) return i + 1;
      ++i;
    }
    return source.size();
  };
  auto skip_space = [&](std::size_t i) {
    while (i < source.size() && std::isspace(static_cast<unsigned char>(source[i]))) ++i;
    return i;
  };
  const std::regex assertion("(EXPECT_[A-Z0-9_]+|ASSERT_[A-Z0-9_]+|ADD_FAILURE|FAIL|GTEST_FAIL)\\s*\\(");
  for (std::size_t i = 0; i < source.size();) {
    const std::size_t after = skip(i);
    if (after != i) {
      i = after;
      continue;
    }
    std::smatch match;
    const bool word_start = i == 0 || !(std::isalnum(static_cast<unsigned char>(source[i - 1])) || source[i - 1] == '_');
    if (!word_start || (source[i] != 'E' && source[i] != 'A' && source[i] != 'F' && source[i] != 'G') ||
        !std::regex_search(source.cbegin() + static_cast<std::ptrdiff_t>(i), source.cend(), match, assertion,
                           std::regex_constants::match_continuous)) {
      ++i;
      continue;
    }
    const std::size_t start = i, end = close(i + static_cast<std::size_t>(match.length(0)) - 1);
    std::size_t next = skip_space(end);
    bool catalogued = false;
    if (source.compare(next, 2, "<<") == 0) {
      next = skip_space(next + 2);
      if (source.compare(next, 13, "failure_text(") == 0) catalogued = source[skip_space(close(next + 12))] == ';';
    }
    if (!catalogued) {
      const std::size_t line = 1 + static_cast<std::size_t>(std::count(source.begin(), source.begin() + static_cast<std::ptrdiff_t>(start), '\n'));
      found.push_back(std::to_string(line) + ": " + source.substr(start, std::min<std::size_t>(end - start, 60)));
    }
    i = end;
  }
  return found;
}

TEST(Messages, SuitesGiveNoTextOutsideTheCatalogue) {
  const std::filesystem::path suites = std::filesystem::path(RAYLAB_SOURCE_DIR) / "autograder" / "suites";
  int files = 0;
  for (const auto& file : std::filesystem::directory_iterator(suites)) {
    std::ifstream in(file.path());
    std::stringstream text;
    text << in.rdbuf();
    ++files;
    EXPECT_EQ(text.str().find("verbatim("), std::string::npos)
        << file.path() << " makes a hint of a text: add it to " << kWhere << " with its English and Chinese texts";
    EXPECT_EQ(text.str().find("MessageId::verbatim"), std::string::npos) << file.path();
    EXPECT_EQ(text.str().find("untranslated("), std::string::npos)
        << file.path() << " gives an English-only text (untranslated): add it to " << kWhere
        << " with its English and Chinese texts";
    EXPECT_EQ(text.str().find("ADD_FAILURE() <<"), std::string::npos)
        << file.path() << " has an ADD_FAILURE: write add_failure({MessageId::your_id, {...}}) with an entry of " << kWhere;
    EXPECT_EQ(text.str().find("<< \""), std::string::npos)
        << file.path() << " streams a text into a failure (<< \"...\"): give it as failure_text({MessageId::your_id, {...}}) "
        << "with an entry of " << kWhere << " (English and Chinese)";
    for (const std::string& assertion : assertions_without_catalogue_text(text.str()))
      ADD_FAILURE() << file.path() << ":" << assertion << ": an assertion's message is one failure_text({MessageId::your_id, "
                    << "{...}}) with an entry of " << kWhere << " (without one, or with a text of its own, --lang zh shows "
                    << "English)";
  }
  EXPECT_GT(files, 0) << suites;
}

TEST(Messages, AssertionCheckFindsTextsOutsideTheCatalogue) {
  // What SuitesGiveNoTextOutsideTheCatalogue must catch, and what it must let pass.
  const std::string source = R"(
    EXPECT_EQ(a, b) << failure_text({MessageId::x, {{"a", f(a)}}});
    ASSERT_TRUE(ok)
        << failure_text(MessageId::y);  // EXPECT_EQ(c, d) in a comment
    const char* s = "EXPECT_EQ(e, f);";
    EXPECT_NEAR(g, h, 1e-3);
    ADD_FAILURE() << result.describe();
    EXPECT_LT(p(i, j), k) << failure_text(MessageId::z) << " and more";
    FAIL();
  )";
  const std::vector<std::string> found = assertions_without_catalogue_text(source);
  ASSERT_EQ(found.size(), 4u) << ::testing::PrintToString(found);
  EXPECT_EQ(found[0].rfind("6: EXPECT_NEAR(g, h, 1e-3)", 0), 0u) << found[0];
  EXPECT_EQ(found[1].rfind("7: ADD_FAILURE()", 0), 0u) << found[1];
  EXPECT_EQ(found[2].rfind("8: EXPECT_LT(p(i, j), k)", 0), 0u) << found[2];
  EXPECT_EQ(found[3].rfind("9: FAIL()", 0), 0u) << found[3];
}

// A broken BVH rule reads in English exactly as the framework writes it (raylab/bvh_tools.h:
// describe), and in Chinese without the English words: every rule, boxes empty and not, the
// push_back note with it and without.
TEST(Messages, BvhRulesMatchTheFrameworksWords) {
  using Rule = BvhViolation::Rule;
  const Bounds3 box{glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 0.5f)};
  std::vector<BvhViolation> cases;
  for (int r = 0; r <= static_cast<int>(Rule::PrimitiveInNoLeaf); ++r)
    for (std::uint64_t value : {0u, 7u}) {
      BvhViolation v;
      v.rule = static_cast<Rule>(r);
      v.index = 3;
      v.value = value;
      v.count = 5;
      v.limit = 12;
      v.box = box;
      v.other_box = value == 0 ? Bounds3{} : box;
      cases.push_back(v);
    }
  const std::regex english_word("(^|[^A-Za-z_])(node|leaf|inner|primitive|has|is|the|in|of|at|expected|children|bounds)([^A-Za-z_]|$)");
  for (const BvhViolation& v : cases) {
    const Message message = bvh_violation_message(v);
    EXPECT_EQ(render(message, Language::English), describe(v)) << "rule " << int(v.rule);
    for (const std::optional<std::string>& mesh : {std::optional<std::string>("scenes/bunny.obj"), std::optional<std::string>()})
      EXPECT_EQ(render(broken_tree_message(v, 42, mesh), Language::English), BrokenBvh(v, 42, mesh).what());
    const std::string chinese = render(message, Language::Chinese);
    EXPECT_FALSE(std::regex_search(chinese, english_word)) << "rule " << int(v.rule) << ": " << chinese;
  }
}

TEST(Messages, RenderFillsPlaceholdersInEitherLanguage) {
  const Message hint{MessageId::sphere_ignores_t_max, {{"t", "5.000000"}, {"t_max", "4.000000"}}};
  EXPECT_EQ(render(hint, Language::English), "ignores t_max: a hit at t = 5.000000 is beyond t_max = 4.000000");
  EXPECT_EQ(render(hint, Language::Chinese), "忽略了 t_max：t = 5.000000 处的交点超出了 t_max = 4.000000");
  // Nested messages are rendered in the same language; a bilingual value picks its language.
  const Message nested{MessageId::console_hint, {{"hint", hint}}};
  EXPECT_EQ(render(nested, Language::English).rfind("hint: ignores t_max", 0), 0u);
  EXPECT_EQ(render(nested, Language::Chinese).rfind("提示：忽略了 t_max", 0), 0u);
  const Message title{MessageId::console_bonus_title, {MessageArg::bilingual("title", "binned SAH build", "分桶 SAH 构建")}};
  EXPECT_EQ(render(title, Language::English), "bonus: binned SAH build");
  EXPECT_EQ(render(title, Language::Chinese), "附加题：分桶 SAH 构建");
  // A placeholder without a value stays visible rather than vanishing.
  EXPECT_EQ(render(Message(MessageId::console_next), Language::English), "next: {what}");
  EXPECT_EQ(render(verbatim("a {b} c"), Language::Chinese), "a {b} c");
}

// A number in a failure text reads short without changing the value the student's code computed:
// GoogleTest's 17 significant digits and the framework's 9 for a float become the shortest text of
// the same float, a double the grader computed gets 6 digits; names, integers and short numbers
// are left alone.
TEST(Messages, NumbersAreShownShort) {
  // GoogleTest's EXPECT_LE and EXPECT_NEAR write doubles with 17 digits, floats promoted to double too.
  EXPECT_EQ(short_numbers("Expected: (a) <= (b), actual: 0.30000000000000004 vs 0.01"),
            "Expected: (a) <= (b), actual: 0.3 vs 0.01");
  EXPECT_EQ(short_numbers("x evaluates to 0.30000001192092896, y to -1.0000001192092896"),
            "x evaluates to 0.3, y to -1.0000001");
  // The framework's vec3 (max_digits10 = 9 per float).
  EXPECT_EQ(short_numbers("returned (0.800000012, -0.707106769, 1)"), "returned (0.8, -0.70710677, 1)");
  // The grader's doubles: 6 digits; a double that is a float's value (2 - 2^-21) keeps what tells it from 2.
  EXPECT_EQ(short_numbers("p = 1.2345678901234567e-05, p = 1.0000000000000001e-50, z = -3.1415926535897931"),
            "p = 1.23457e-05, p = 1e-50, z = -3.14159");
  EXPECT_EQ(short_numbers("the exact answer is 1.9999995231628418"), "the exact answer is 1.9999995");
  // A float that needs its 8 or 9 digits keeps them: nothing the student's code computed is lost.
  EXPECT_EQ(short_numbers("t = 1.0000001 and 0.123456791"), "t = 1.0000001 and 0.12345679");
  for (const float value : {1.0000001f, 0.1f, 3.14159274f, 1e-7f, 123456.789f, -2.5e30f}) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", static_cast<double>(value));
    EXPECT_EQ(std::strtof(short_numbers(text).c_str(), nullptr), value) << text << " -> " << short_numbers(text);
  }
  // Short numbers, integers, std::to_string's six decimals and digits inside names stay.
  for (const char* same : {"t = 4.000000, t_max = 1.41421", "20000 samples, seed 4294967295", "Stage09Path, 09_path, 4x4",
                           "GoogleTest 1.12.1", "grading-output/09_path-cornell.png", "chi-square 12.34 (p = 0.001)",
                           "0.5, -0.25, 1e-05", "NaN and infinity"})
    EXPECT_EQ(short_numbers(same), same);
}

TEST(Messages, LanguageFromItsNameAndTheEnvironment) {
  EXPECT_EQ(parse_language("zh"), Language::Chinese);
  EXPECT_EQ(parse_language("zh_CN.UTF-8"), Language::Chinese);
  EXPECT_EQ(parse_language("zh-TW"), Language::Chinese);
  EXPECT_EQ(parse_language("en_US.UTF-8"), Language::English);
  EXPECT_EQ(parse_language("C"), Language::English);
  EXPECT_EQ(parse_language("zhx"), std::nullopt);
  EXPECT_EQ(parse_language("fr_FR"), std::nullopt);

  unset_variable("LC_ALL");
  unset_variable("LC_MESSAGES");
  set_variable("LANG", "zh_CN.UTF-8");
  EXPECT_EQ(language_from_environment(), Language::Chinese);
  set_variable("LC_MESSAGES", "en_GB.UTF-8");  // more specific than LANG
  EXPECT_EQ(language_from_environment(), Language::English);
  set_variable("LC_ALL", "zh_CN.UTF-8");  // overrides both
  EXPECT_EQ(language_from_environment(), Language::Chinese);
#ifndef _WIN32  // Windows has no variable that is set but empty
  set_variable("LC_ALL", "");  // set but empty: the next one decides
  EXPECT_EQ(language_from_environment(), Language::English);
#endif
  unset_variable("LC_ALL");
  unset_variable("LC_MESSAGES");
  set_variable("LANG", "fr_FR.UTF-8");  // no French catalogue
  EXPECT_EQ(language_from_environment(), Language::English);
  unset_variable("LANG");
  EXPECT_EQ(language_from_environment(), Language::English);
}

// Text a stage wrote (an exception's message, what it printed) reaches the console, the HTML
// report and results.json: nothing in it may act as anything but text.
TEST(ShownAsText, ControlAndInvisibleCharactersBecomeQuestionMarks) {
  EXPECT_EQ(shown_as_text("plain text, 中文 and t = 0.5\tok"), "plain text, 中文 and t = 0.5\tok");
  EXPECT_EQ(shown_as_text("\033[2J\033[Hclear\r"), "?[2J?[Hclear?");            // C0 escapes and CR
  EXPECT_EQ(shown_as_text("\xC2\x9B" "2J and \xC2\x85 and \x7F"), "?2J and ? and ?");  // C1 CSI, NEL; DEL
  EXPECT_EQ(shown_as_text("score \xE2\x80\xAE" "02/001\xE2\x80\xAC"), "score ?02/001?");  // RLO ... PDF
  EXPECT_EQ(shown_as_text("a\xE2\x80\x8B" "b\xE2\x81\xA6" "c\xEF\xBB\xBF" "d\xD8\x9C" "e\xE2\x80\xA8" "f"),
            "a?b?c?d?e?f");  // zero-width space, isolate, BOM, Arabic mark, line separator
  EXPECT_EQ(shown_as_text("bad \xFF\xC0\x80 \xE4\xB8"), "bad ??? ??");  // not UTF-8, overlong, cut short
  EXPECT_EQ(shown_as_text(std::string("nul\0byte", 8)), "nul?byte");
}

TEST(MarkdownText, StageTextCannotMarkUpTheGradescopePage) {
  // The catalogue's code spans stay spans; nothing inside one is live.
  EXPECT_EQ(markdown_text("write `generate_camera_ray` in `a_b*c`"), "write `generate_camera_ray` in `a_b*c`");
  // Bold, links, images, tags, headings, tables, entities: escaped, so shown as the characters they are.
  EXPECT_EQ(markdown_text("**All tests passed**"), "\\*\\*All tests passed\\*\\*");
  EXPECT_EQ(markdown_text("![t](http://x/t.png) [here](http://x)"), "\\!\\[t\\](http://x/t.png) \\[here\\](http://x)");
  EXPECT_EQ(markdown_text("<img src=x> # Score | 40 &amp; ~~no~~"),
            "\\<img src=x\\> \\# Score \\| 40 \\&amp; \\~\\~no\\~\\~");
  // A backtick that opens no span is escaped: it cannot swallow what follows.
  EXPECT_EQ(markdown_text("one ` tick **b**"), "one \\` tick \\*\\*b\\*\\*");
  // Control characters go first (shown_as_text).
  EXPECT_EQ(markdown_text("\xE2\x80\xAE" "x"), "?x");
}

}  // namespace
}  // namespace raylab::grading
