#include "option_error.hpp"

#include <string_view>

#include "pmdplan/core/message_text.hpp"

namespace pmdplan::cli {
namespace {

/// The innermost subcommand the command line named ("pmdplan time", "pmdplan robot init").
const CLI::App& commandParsed(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands())
    if (sub->parsed()) return commandParsed(*sub);
  return app;
}

std::string commandName(const CLI::App& app) {
  std::string name = app.get_name();
  for (const CLI::App* parent = app.get_parent(); parent; parent = parent->get_parent())
    name = (parent->get_parent() ? parent->get_name() : std::string("pmdplan")) + " " + name;
  return app.get_parent() ? name : "pmdplan";
}

/// CLI11's type names as the values they expect.
std::string expectedValue(const std::string& type) {
  if (type.rfind("FLOAT", 0) == 0) return "a number";
  if (type.rfind("UINT", 0) == 0) return "a whole number >= 0";
  if (type.rfind("INT", 0) == 0) return "a whole number";
  if (type.rfind("BOOLEAN", 0) == 0) return "true or false";
  return "a value";
}

std::string typeOf(const CLI::App& command, const std::string& name) {
  for (const CLI::Option* option : command.get_options())
    if (option->check_name(name)) return option->get_type_name();
  return "";
}

/// Everything after `prefix` in `text`, or "" when `text` does not start with it.
std::string after(const std::string& text, std::string_view prefix) {
  return text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : std::string();
}

std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

}  // namespace

std::string optionErrorLine(const CLI::ParseError& error, const CLI::App& app) {
  const CLI::App& command = commandParsed(app);
  const std::string name = commandName(command);
  const std::string help = "; see `" + name + " --help`";
  const std::string what = oneLine(error.what());
  if (dynamic_cast<const CLI::ConversionError*>(&error)) {
    // "Could not convert: --blend-tolerance = abc"
    const std::string rest = after(what, "Could not convert: ");
    const auto equals = rest.find(" = ");
    if (equals != std::string::npos) {
      const std::string option = rest.substr(0, equals);
      return option + ": expected " + expectedValue(typeOf(command, option)) + ", got " +
             quotedText(rest.substr(equals + 3));
    }
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
    const auto colon = what.find(": ");
    const std::string option = colon == std::string::npos ? "option" : what.substr(0, colon);
    if (what.find("At Most") != std::string::npos)  // "--seed: At Most 1 required but received 2"
      return option + ": given more than once; expected it at most once";
    if (what.find("missing") != std::string::npos)  // "--task: 1 required TEXT missing"
      return option + ": expected " + expectedValue(typeOf(command, option)) + " after it";
    return option + ": " + what.substr(colon == std::string::npos ? 0 : colon + 2) + help;
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    // "The following argument(s) was/were not expected: a b"
    const auto colon = what.find(": ");
    const std::string extras = colon == std::string::npos ? what : what.substr(colon + 2);
    return quotedText(extras) + ": not expected by `" + name + "`" + help;
  }
  if (dynamic_cast<const CLI::RequiredError*>(&error)) {
    if (what.find("subcommand") != std::string::npos) {
      std::string names;
      for (const CLI::App* sub : command.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
      return "command: expected one of " + names + help;
    }
    std::string option = what;  // "--palm is required", "urdf is required"
    if (const auto is = option.find(" is required"); is != std::string::npos) option.erase(is);
    return option + ": required" + help;
  }
  // ValidationError and the rest already start with the option's name ("--samples: expected …").
  return what.find(": ") != std::string::npos ? what : "arguments: " + what + help;
}

}  // namespace pmdplan::cli
