// A student file's bytes as Lua is given them, and the note for text that is not UTF-8 (lua_source.h): a UTF-8 byte
// order mark goes, a shebang becomes a comment, and UTF-16 or a stray Latin-1 byte is named with its line; UTF-8 text
// in any script (accents, CJK, emoji) has no note.
#include <gtest/gtest.h>

#include <string>

#include "script/lua_source.h"

namespace meshedit {
namespace {

TEST(LuaSource, DropsAByteOrderMarkAndCommentsAShebangAsLuaCDoes) {
  EXPECT_EQ(lua_source_text("\xEF\xBB\xBFreturn 1\n"), "return 1\n");
  EXPECT_EQ(lua_source_text("#!/usr/bin/lua\nreturn 1\n"), "--#!/usr/bin/lua\nreturn 1\n");
  EXPECT_EQ(lua_source_text("\xEF\xBB\xBF#!lua\nreturn 1\n"), "--#!lua\nreturn 1\n");
  EXPECT_EQ(lua_source_text("return '#'\n"), "return '#'\n");
}

TEST(LuaSource, UTF8TextHasNoNote) {
  EXPECT_EQ(encoding_note("return 1\n", "flip.lua"), "");
  EXPECT_EQ(encoding_note("-- caf\xC3\xA9, \xE5\x8D\x8A\xE8\xBE\xB9, \xF0\x9F\x98\x80\nreturn 1\n", "flip.lua"), "");
  EXPECT_EQ(encoding_note("", "flip.lua"), "");
}

TEST(LuaSource, UTF16AndStrayBytesAreNamedWithTheirLine) {
  const std::string utf16("\xFF\xFEr\0e\0t\0", 8);
  EXPECT_EQ(encoding_note(utf16, "flip.lua"), "flip.lua is UTF-16 text, which Lua cannot read: save it as UTF-8");
  const std::string without_mark("r\0e\0t\0u\0r\0n\0", 12);
  EXPECT_EQ(encoding_note(without_mark, "flip.lua"),
            "flip.lua is UTF-16 text, which Lua cannot read: save it as UTF-8");
  EXPECT_EQ(encoding_note("return 1\n-- caf\xE9\n", "split.lua"),
            "split.lua is not UTF-8 text (line 2 has the byte 0xE9): save it as UTF-8");
  EXPECT_EQ(encoding_note("-- \xED\xA0\x80 a surrogate\n", "a.lua"),
            "a.lua is not UTF-8 text (line 1 has the byte 0xED): save it as UTF-8");
  EXPECT_EQ(encoding_note("-- \xC0\xAF overlong\n", "a.lua"),
            "a.lua is not UTF-8 text (line 1 has the byte 0xC0): save it as UTF-8");
  EXPECT_EQ(encoding_note("-- cut \xE5\x8D", "a.lua"),
            "a.lua is not UTF-8 text (line 1 has the byte 0xE5): save it as UTF-8");
}

TEST(LuaSource, TheNoteFollowsTheError) {
  EXPECT_EQ(with_encoding_note("flip.lua:1: unexpected symbol", "ok\n", "flip.lua"), "flip.lua:1: unexpected symbol");
  EXPECT_EQ(with_encoding_note("flip.lua:2: unexpected symbol", "x\n\xE9", "flip.lua"),
            "flip.lua:2: unexpected symbol (flip.lua is not UTF-8 text (line 2 has the byte 0xE9): save it as UTF-8)");
}

}  // namespace
}  // namespace meshedit
