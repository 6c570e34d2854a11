// The autograder's catalogue (autograder/runner/messages.def): every message in English and
// Simplified Chinese with the same placeholders and the twin handout's sections, every stage
// title in both languages, and no hint that bypasses the catalogue. The ctest messages_are_paired.
#include "messages.h"

#include "raylab/stage_table.h"

#include <gtest/gtest.h>

#include <algorithm>
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

const char* const kWhere = "autograder/runner/messages.def";

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
// assertion (ADD_FAILURE() << "...", EXPECT_EQ(...) << "..."). Hints and notes: no exception. Suites
// whose failure texts (what a test expected and what came back) are still English only: named in
// the output, those checks skipped. This list only shrinks; a suite not on it fails.
const char* const kSuitesWithEnglishFailures[] = {"07_sampling_test.cpp"};

TEST(Messages, SuitesGiveNoTextOutsideTheCatalogue) {
  const std::filesystem::path suites = std::filesystem::path(RAYLAB_SOURCE_DIR) / "autograder" / "suites";
  int files = 0;
  for (const auto& file : std::filesystem::directory_iterator(suites)) {
    const std::string name = file.path().filename().string();
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
    if (std::find(std::begin(kSuitesWithEnglishFailures), std::end(kSuitesWithEnglishFailures), name) !=
        std::end(kSuitesWithEnglishFailures)) {
      std::printf("still to translate: the failure texts of autograder/suites/%s (English in both languages: "
                  "move each into %s); its hints and notes are checked\n", name.c_str(), kWhere);
      continue;
    }
    EXPECT_EQ(text.str().find("ADD_FAILURE() <<"), std::string::npos)
        << file.path() << " has an ADD_FAILURE: write add_failure({MessageId::your_id, {...}}) with an entry of " << kWhere;
    EXPECT_EQ(text.str().find("<< \""), std::string::npos)
        << file.path() << " streams a text into a failure (<< \"...\"): give it as failure_text({MessageId::your_id, {...}}) "
        << "with an entry of " << kWhere << " (English and Chinese)";
  }
  EXPECT_GT(files, 0) << suites;
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

}  // namespace
}  // namespace raylab::grading
