// Everything the autograder tells a student, in English and Simplified Chinese: one catalogue
// (messages.def: an id and its two texts), the language of this run, and a Message, which is an
// id with the values of its placeholders, rendered in either language when it is shown.
//
//   add_hint({MessageId::sphere_hit_behind, {{"t", std::to_string(t)}}});
//
// shows "returns a hit behind the ray (t = -1.000000): ..." or its Chinese text: the texts of
// sphere_hit_behind in its stage's catalogue both hold the placeholder {t}. A new hint is a new
// entry in the stage's catalogue, autograder/suites/<id>_messages.def (messages.def includes it),
// with both texts (the test messages_are_paired fails on an entry without its
// Chinese text); docs/zh/glossary.md lists the Chinese terms the texts use.
#pragma once

#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace raylab::grading {

enum class Language { English, Chinese };

enum class MessageId : int {
#define RAYLAB_MESSAGE(id, english, chinese) id,
#include "messages.def"
#undef RAYLAB_MESSAGE
};

struct MessageArg;

// An id and the values of its placeholders. A value is a text (numbers formatted by the caller,
// the same in both languages) or other messages, rendered in the same language and joined.
struct Message {
  MessageId id;
  std::vector<MessageArg> args;
  Message(MessageId message_id);  // NOLINT: implicit, so that add_hint(MessageId::x) reads well
  Message(MessageId message_id, std::vector<MessageArg> message_args);
  bool operator==(const Message& other) const;
};

struct MessageArg {
  std::string name;           // the placeholder {name}
  std::string text;           // its value ...
  std::vector<Message> parts; // ... followed by these, rendered and joined
  std::optional<std::string> chinese_text;  // if set: the value in Chinese (a stage's title, a handout's path)
  static MessageArg bilingual(std::string arg_name, std::string english, std::string chinese);
  MessageArg(std::string arg_name, std::string value);
  MessageArg(std::string arg_name, const char* value);
  MessageArg(std::string arg_name, Message part);
  MessageArg(std::string arg_name, std::vector<Message> message_parts);
  bool operator==(const MessageArg& other) const;
};

// A text in `language`: its catalogue template with each {name} replaced by its argument.
std::string render(const Message& message, Language language);
// In this run's language.
std::string render(const Message& message);
// The text of messages that wrap a text that has no translation (a failure message of an
// assertion, a framework error), shown as it is in both languages.
Message verbatim(std::string text);

// "sphere_hit_behind": the id as results.json names it.
std::string_view message_name(MessageId id);

// The catalogue, in the order of messages.def.
struct CatalogueEntry {
  MessageId id;
  std::string_view name, english, chinese;
};
const std::vector<CatalogueEntry>& message_catalogue();
// The placeholders of a template: the names between { and } (letters, digits, '_').
std::vector<std::string> placeholders_of(std::string_view text);

// This run's language: --lang if given, otherwise the environment (LC_ALL, LC_MESSAGES, LANG:
// the first that is set and not empty; a value starting with "zh" is Chinese), otherwise English.
Language language();
void set_language(Language language);
Language language_from_environment();
// "en" or "zh" (also "zh_CN", "zh-CN", "zh_CN.UTF-8", "en_US" ...); nullopt otherwise.
std::optional<Language> parse_language(std::string_view name);

// A number as a stream writes it by default (6 significant digits), the format of many texts.
template <typename Number>
std::string stream_text(Number value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// A text with its numbers short: GoogleTest writes a number with 17 significant digits
// (0.30000001192092896 for 0.3f, 0.30000000000000004 for 0.1 + 0.2), the framework's operator<<
// a float with 9 (0.800000012). A float's value (9 digits at most, or 17 that are exactly a
// float's) becomes the shortest text that reads back as the same float (0.3, 0.8, 1.0000001): the
// precision of every value a stage function returns, so nothing the student's code computed is
// lost; any other number of more than 9 digits (a double the grader computed: a mean, a z-score,
// 0.1 + 0.2) gets 6 significant digits, as a stream writes it by default (0.3, -119.906).
// Integers, numbers of fewer than 8 digits and digits inside a name (Stage09Path, 09_path, 4x4,
// 1.12.2) stay as they are. The judge applies it to every failure, hint and note a test records
// (grading.cpp), so a number reads the same wherever it was formatted.
std::string short_numbers(const std::string& text);

// The length of the UTF-8 sequence at text[i], or 0 if it is not one (overlong, a surrogate,
// beyond U+10FFFF, cut short).
std::size_t utf8_length(std::string_view text, std::size_t i);

// A line as the grader shows it, whoever wrote it (a stage's exception text or output may say
// anything): every character that is not plain visible text becomes '?': C0 controls but tab
// (escape sequences that move the cursor or rewrite the table above), DEL, C1 controls (which
// some terminals also take as escape sequences), bidirectional controls and other invisible
// format characters (which reorder or hide what is shown: U+061C, U+180E, U+200B-U+200F,
// U+2028-U+202E, U+2060-U+206F, U+FEFF, U+FFF9-U+FFFB), and bytes that are not UTF-8.
std::string shown_as_text(std::string_view line);

// A line of the grader's text as Markdown (results.json's output for Gradescope), shown as text
// whoever wrote it: the catalogue's `code` spans stay spans (nothing inside one is live); outside
// them every character that starts Markdown or HTML markup is escaped (emphasis, links and
// images, headings, tables, quotes, tags, entities), and so is a backtick that opens no span;
// after shown_as_text.
std::string markdown_text(std::string_view line);

// A hint or note given as text fails to compile with this message: each is a catalogue entry.
template <typename Text, typename = std::enable_if_t<std::is_convertible_v<Text, std::string_view>>>
void add_hint(const Text&) {
  static_assert(!std::is_convertible_v<Text, std::string_view>,
                "add_hint takes a Message, not a text: add the hint to autograder/suites/<stage>_messages.def as "
                "RAYLAB_MESSAGE(your_id, \"English text with {placeholders}\", \"Chinese text with the same "
                "{placeholders}\") and call add_hint({MessageId::your_id, {{\"placeholder\", value}}})");
}
template <typename Text, typename = std::enable_if_t<std::is_convertible_v<Text, std::string_view>>>
void add_note(const Text&) {
  static_assert(!std::is_convertible_v<Text, std::string_view>,
                "add_note takes a Message, not a text: add the note to autograder/suites/<stage>_messages.def as "
                "RAYLAB_MESSAGE(your_id, \"English text with {placeholders}\", \"Chinese text with the same "
                "{placeholders}\") and call add_note({MessageId::your_id, {{\"placeholder\", value}}})");
}

}  // namespace raylab::grading
