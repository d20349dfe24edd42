// The command table's keys as GLFW keys (see commands.h).
#include "app/commands.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <vector>

namespace meshedit {
namespace {

// Keys named by a word or a character other than a letter, as the table writes them.
struct NamedKey {
  std::string_view text;
  int key;
};
constexpr NamedKey kNamedKeys[] = {
    {"Space", GLFW_KEY_SPACE},
    {"Esc", GLFW_KEY_ESCAPE},
    {"F1", GLFW_KEY_F1},
    {"`", GLFW_KEY_GRAVE_ACCENT},
    {"[", GLFW_KEY_LEFT_BRACKET},
    {"]", GLFW_KEY_RIGHT_BRACKET},
    {"=", GLFW_KEY_EQUAL},
    {"-", GLFW_KEY_MINUS},
    {"0", GLFW_KEY_0},
    {"keypad +", GLFW_KEY_KP_ADD},
    {"keypad -", GLFW_KEY_KP_SUBTRACT},
    {"keypad 0", GLFW_KEY_KP_0},
};

bool has_key(const Command& c, int key, KeyMods mods) {
  for (const char* text : {c.key, c.other_key}) {
    if (!text) continue;
    const std::optional<KeyChord> chord = parse_key_text(text);
    if (chord && chord->key == key && chord->mods.ctrl == mods.ctrl && chord->mods.shift == mods.shift) return true;
  }
  return false;
}

}  // namespace

std::optional<KeyChord> parse_key_text(std::string_view text) {
  KeyChord chord;
  for (;;) {
    if (text.starts_with("Ctrl+") && text.size() > 5) {
      chord.mods.ctrl = true;
      text.remove_prefix(5);
    } else if (text.starts_with("Shift+") && text.size() > 6) {
      chord.mods.shift = true;
      text.remove_prefix(6);
    } else {
      break;
    }
  }
  if (text.size() == 1 && text[0] >= 'A' && text[0] <= 'Z') {
    chord.key = GLFW_KEY_A + (text[0] - 'A');
    return chord;
  }
  for (const NamedKey& named : kNamedKeys) {
    if (text == named.text) {
      chord.key = named.key;
      return chord;
    }
  }
  return std::nullopt;
}

const Command* find_key_command(int key, KeyMods mods, CommandView view) {
  for (const CommandView where : {view, CommandView::Everywhere}) {
    for (const Command& c : commands()) {
      if (c.view == where && has_key(c, key, mods)) return &c;
    }
    if (view == CommandView::Everywhere) break;
  }
  return nullptr;
}

std::optional<KeyChord> command_key(const Command& command) {
  return command.key ? parse_key_text(command.key) : std::nullopt;
}

std::span<const int> bound_keys() {
  static const std::vector<int> kKeys = [] {
    std::vector<int> all;
    for (const Command& c : commands()) {
      for (const char* text : {c.key, c.other_key}) {
        const std::optional<KeyChord> chord = text ? parse_key_text(text) : std::nullopt;
        if (chord && std::find(all.begin(), all.end(), chord->key) == all.end()) all.push_back(chord->key);
      }
    }
    return all;
  }();
  return kKeys;
}

std::string lesson_key_name(int key, KeyMods mods) {
  std::string name;
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) name = std::string(1, char('A' + (key - GLFW_KEY_A)));
  else if (key == GLFW_KEY_SPACE) name = "Space";
  else if (key == GLFW_KEY_ESCAPE) name = "Escape";
  else return {};
  if (mods.shift) name = "shift+" + name;
  if (mods.ctrl) name = "ctrl+" + name;
  return name;
}

}  // namespace meshedit
