#include "messages.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace raylab::grading {

Message::Message(MessageId message_id) : id(message_id) {}
Message::Message(MessageId message_id, std::vector<MessageArg> message_args) : id(message_id), args(std::move(message_args)) {}
bool Message::operator==(const Message& other) const { return id == other.id && args == other.args; }

MessageArg::MessageArg(std::string arg_name, std::string value) : name(std::move(arg_name)), text(std::move(value)) {}
MessageArg::MessageArg(std::string arg_name, const char* value) : name(std::move(arg_name)), text(value) {}
MessageArg::MessageArg(std::string arg_name, Message part) : name(std::move(arg_name)), parts{std::move(part)} {}
MessageArg::MessageArg(std::string arg_name, std::vector<Message> message_parts)
    : name(std::move(arg_name)), parts(std::move(message_parts)) {}
MessageArg MessageArg::bilingual(std::string arg_name, std::string english, std::string chinese) {
  MessageArg arg(std::move(arg_name), std::move(english));
  arg.chinese_text = std::move(chinese);
  return arg;
}
bool MessageArg::operator==(const MessageArg& other) const {
  return name == other.name && text == other.text && parts == other.parts && chinese_text == other.chinese_text;
}

const std::vector<CatalogueEntry>& message_catalogue() {
  static const std::vector<CatalogueEntry> catalogue = {
#define RAYLAB_MESSAGE(id, english, chinese) {MessageId::id, #id, english, chinese},
#include "messages.def"
#undef RAYLAB_MESSAGE
  };
  return catalogue;
}

std::string_view message_name(MessageId id) { return message_catalogue().at(static_cast<std::size_t>(id)).name; }

namespace {

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The placeholder starting at text[i] ('{'): its length up to and with '}', or 0 if none.
std::size_t placeholder_length(std::string_view text, std::size_t i) {
  std::size_t end = i + 1;
  while (end < text.size() && is_name_char(text[end])) ++end;
  return end > i + 1 && end < text.size() && text[end] == '}' ? end - i + 1 : 0;
}

Language& language_storage() {
  static Language language = language_from_environment();
  return language;
}

}  // namespace

std::vector<std::string> placeholders_of(std::string_view text) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '{')
      if (const std::size_t length = placeholder_length(text, i)) names.emplace_back(text.substr(i + 1, length - 2));
  return names;
}

std::string render(const Message& message, Language language) {
  const CatalogueEntry& entry = message_catalogue().at(static_cast<std::size_t>(message.id));
  const std::string_view text = language == Language::Chinese ? entry.chinese : entry.english;
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = text[i] == '{' ? placeholder_length(text, i) : 0;
    const MessageArg* arg = nullptr;
    if (length > 0)
      for (const MessageArg& candidate : message.args)
        if (text.substr(i + 1, length - 2) == candidate.name) arg = &candidate;
    if (!arg) {  // a plain character, or a placeholder without a value: shown as it is
      out += text[i++];
      continue;
    }
    out += language == Language::Chinese && arg->chinese_text ? *arg->chinese_text : arg->text;
    for (const Message& part : arg->parts) out += render(part, language);
    i += length;
  }
  return out;
}

std::string render(const Message& message) { return render(message, language()); }

Message verbatim(std::string text) { return {MessageId::verbatim, {{"text", std::move(text)}}}; }

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The significant digits of a number's text: "0.30000000000000004" 17, "0.500000" 1, "100" 3.
std::size_t significant_digits(std::string_view number) {
  const std::string_view mantissa = number.substr(0, number.find_first_of("eE"));
  std::string digits;
  for (const char c : mantissa)
    if (is_digit(c)) digits += c;
  const std::size_t first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  std::size_t last = digits.size();
  if (mantissa.find('.') != std::string_view::npos)  // a fraction's trailing zeros say nothing
    while (last > first + 1 && digits[last - 1] == '0') --last;
  return last - first;
}

// One number of 8 or more significant digits: a float's (9 digits at most, or exactly a float's
// value) as the shortest text that reads back as the same float ("%g" with 1 to 9 digits); a
// double's (more than 9 digits, not a float's value: a statistic the grader computed) with 6
// ("%.6g"); as it is when that is no shorter.
std::string short_number(const std::string& number) {
  const std::size_t digits = significant_digits(number);
  if (digits < 8) return number;
  const double value = std::strtod(number.c_str(), nullptr);
  if (!std::isfinite(value)) return number;
  char text[48];
  const bool in_float_range = value == 0.0 || (std::fabs(value) <= static_cast<double>(std::numeric_limits<float>::max()) &&
                                                std::fabs(value) >= static_cast<double>(std::numeric_limits<float>::min()));
  const bool a_float = in_float_range && (digits <= 9 || static_cast<double>(static_cast<float>(value)) == value);
  if (!a_float) {
    std::snprintf(text, sizeof text, "%.6g", value);
  } else {
    const float single = static_cast<float>(value);
    for (int precision = 1; precision <= 9; ++precision) {
      std::snprintf(text, sizeof text, "%.*g", precision, static_cast<double>(single));
      if (std::strtof(text, nullptr) == single) break;
    }
  }
  return significant_digits(text) < digits ? std::string(text) : number;
}

}  // namespace

std::string short_numbers(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    // A number starts at a digit that does not continue a name or another number (09 in
    // Stage09Path, 2 in 1.12.2).
    const bool starts = is_digit(text[i]) && (i == 0 || !(is_name_char(text[i - 1]) || text[i - 1] == '.'));
    if (!starts) {
      out += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && is_digit(text[end])) ++end;
    bool decimal = false;  // with a fraction or an exponent: an integer is left as it is
    if (end + 1 < text.size() && text[end] == '.' && is_digit(text[end + 1])) {
      decimal = true;
      for (++end; end < text.size() && is_digit(text[end]);) ++end;
    }
    if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
      std::size_t digit = end + 1;
      if (digit < text.size() && (text[digit] == '+' || text[digit] == '-')) ++digit;
      if (digit < text.size() && is_digit(text[digit])) {
        decimal = true;
        for (end = digit; end < text.size() && is_digit(text[end]);) ++end;
      }
    }
    // ... and ends where no name or further number goes on (4x4, 1.12.2, 2e3x).
    const bool ends = end == text.size() ||
                      !(is_name_char(text[end]) || (text[end] == '.' && end + 1 < text.size() && is_digit(text[end + 1])));
    const std::string number = text.substr(i, end - i);
    out += decimal && ends ? short_number(number) : number;
    i = end;
  }
  return out;
}

std::optional<Language> parse_language(std::string_view name) {
  auto starts = [&](std::string_view prefix) {
    if (name.substr(0, prefix.size()) != prefix) return false;
    return name.size() == prefix.size() || !std::isalpha(static_cast<unsigned char>(name[prefix.size()]));
  };
  if (starts("zh")) return Language::Chinese;
  if (starts("en") || name == "C" || name == "POSIX" || starts("C.")) return Language::English;
  return std::nullopt;
}

Language language_from_environment() {
  for (const char* variable : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
    const char* value = std::getenv(variable);
    if (!value || !*value) continue;
    // The first variable that is set decides (POSIX's order); a language without a catalogue
    // (fr_FR, ...) is English.
    return parse_language(value) == Language::Chinese ? Language::Chinese : Language::English;
  }
  return Language::English;
}

Language language() { return language_storage(); }
void set_language(Language language) { language_storage() = language; }

std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u; };
  const unsigned lead = byte(0);
  const auto continuation = [&](std::size_t k, unsigned low = 0x80, unsigned high = 0xBF) {
    return byte(k) >= low && byte(k) <= high;
  };
  if (lead >= 0xC2 && lead <= 0xDF) return continuation(1) ? 2 : 0;
  if (lead >= 0xE0 && lead <= 0xEF) {
    const unsigned low = lead == 0xE0 ? 0xA0 : 0x80, high = lead == 0xED ? 0x9F : 0xBF;
    return continuation(1, low, high) && continuation(2) ? 3 : 0;
  }
  if (lead >= 0xF0 && lead <= 0xF4) {
    const unsigned low = lead == 0xF0 ? 0x90 : 0x80, high = lead == 0xF4 ? 0x8F : 0xBF;
    return continuation(1, low, high) && continuation(2) && continuation(3) ? 4 : 0;
  }
  return 0;
}

std::string shown_as_text(std::string_view line) {
  std::string text;
  text.reserve(line.size());
  for (std::size_t i = 0; i < line.size();) {
    const unsigned char lead = static_cast<unsigned char>(line[i]);
    if (lead < 0x80) {
      text += (lead < 32 && lead != '\t') || lead == 127 ? '?' : static_cast<char>(lead);
      ++i;
      continue;
    }
    const std::size_t length = utf8_length(line, i);
    if (length == 0) {
      text += '?';
      ++i;
      continue;
    }
    char32_t code = lead & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) code = code << 6 | (static_cast<unsigned char>(line[i + k]) & 0x3F);
    const bool hidden = (code >= 0x80 && code <= 0x9F) || code == 0x61C || code == 0x180E ||
                        (code >= 0x200B && code <= 0x200F) || (code >= 0x2028 && code <= 0x202E) ||
                        (code >= 0x2060 && code <= 0x206F) || code == 0xFEFF || (code >= 0xFFF9 && code <= 0xFFFB);
    if (hidden) text += '?';
    else text.append(line.substr(i, length));
    i += length;
  }
  return text;
}

std::string markdown_text(std::string_view line) {
  const std::string text = shown_as_text(line);
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '`') {
      const std::size_t close = text.find('`', i + 1);
      if (close != std::string::npos) {  // a code span, as it is
        out.append(text, i, close + 1 - i);
        i = close + 1;
        continue;
      }
    }
    if (std::strchr("\\`*_[]<>!#|~&", text[i]) != nullptr) out += '\\';
    out += text[i++];
  }
  return out;
}

}  // namespace raylab::grading
