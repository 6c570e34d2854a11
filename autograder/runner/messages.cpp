#include "messages.h"

#include <cctype>
#include <cstdlib>

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

}  // namespace raylab::grading
