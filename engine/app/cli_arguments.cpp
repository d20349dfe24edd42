// Small argument helpers shared by the commands (see cli_commands.h).
#include <charconv>

#include "app/cli_commands.h"
#include "core/patch_tessellation.h"

namespace meshedit {

std::optional<std::string> take_option(std::vector<std::string>& args, const std::string& name,
                                       const std::string& short_name) {
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != name && (short_name.empty() || args[i] != short_name)) continue;
    if (i + 1 >= args.size()) throw UsageError(args[i] + " needs a value");
    std::string value = args[i + 1];
    args.erase(args.begin() + long(i), args.begin() + long(i) + 2);
    return value;
  }
  return std::nullopt;
}

bool take_flag(std::vector<std::string>& args, const std::string& name) {
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == name) {
      args.erase(args.begin() + long(i));
      return true;
    }
  }
  return false;
}

int parse_count(const std::string& text, const std::string& option, int max) {
  int value = -1;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 0 || value > max) {
    throw UsageError(option + " must be a whole number from 0 to " + std::to_string(max) + ", not '" + text + "'");
  }
  return value;
}

int take_resolution_option(std::vector<std::string>& args) {
  const auto text = take_option(args, "--resolution");
  return text ? parse_count(*text, "--resolution", 256) : kDefaultPatchResolution;
}

void reject_unknown_options(const std::vector<std::string>& args) {
  for (const auto& a : args) {
    if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option '" + a + "'");
  }
}

}  // namespace meshedit
