#!/usr/bin/env python3
"""The page's Chinese font: WenQuanYi Micro Hei cut down to the characters the page can show.

Keeps every wide character (CJK, kana, full-width forms) of the shipped lessons (lessons/*.lua) and of the window's
catalogs (assets/translations/*/*.po), CJK punctuation and full-width forms, and the 2,500 common Simplified Chinese
characters of ImGui's GetGlyphRangesChineseSimplifiedCommon (read from the imgui_draw.cpp given, so the list is
ImGui's own), so a student's own Chinese comment is drawn too. The desktop reads the whole font from Debian's
fonts-wqy-microhei instead (engine/ui/fonts.cpp).

Usage: font_subset.py SOURCE_DIR IMGUI_DRAW_CPP FONT.ttc OUT.ttf
"""
import glob
import os
import re
import subprocess
import sys


def wide(code):
    return (0x2E80 <= code <= 0x9FFF or 0xAC00 <= code <= 0xD7AF or 0xF900 <= code <= 0xFAFF
            or 0xFE30 <= code <= 0xFE4F or 0xFF00 <= code <= 0xFFEF)


def shipped_characters(source):
    files = glob.glob(os.path.join(source, "lessons", "*.lua"))
    files += glob.glob(os.path.join(source, "assets", "translations", "*", "*.po"))
    found = set()
    for name in files:
        with open(name, encoding="utf-8") as f:
            found.update(c for c in f.read() if wide(ord(c)))
    return found


def imgui_common_characters(imgui_draw):
    with open(imgui_draw, encoding="utf-8") as f:
        text = f.read()
    match = re.search(r"accumulative_offsets_from_0x4E00\[\]\s*=\s*\{([^}]*)\}", text)
    if not match:
        sys.exit(f"font_subset: no accumulative_offsets_from_0x4E00 in {imgui_draw}")
    code, found = 0x4E00, set()
    for offset in match.group(1).replace("\n", "").split(","):
        if offset.strip():
            code += int(offset)
            found.add(chr(code))
    return found


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    source, imgui_draw, font, out = sys.argv[1:]
    characters = shipped_characters(source) | imgui_common_characters(imgui_draw)
    text_file = out + ".characters.txt"
    with open(text_file, "w", encoding="utf-8") as f:
        f.write("".join(sorted(characters)))
    subprocess.run(["pyftsubset", font, "--font-number=0", f"--text-file={text_file}",
                    "--unicodes=U+3000-303F,U+FF00-FFEF,U+2010-2027", f"--output-file={out}", "--no-hinting",
                    "--drop-tables+=FFTM"], check=True)
    print(f"font_subset: {len(characters)} characters, {os.path.getsize(out)} bytes in {out}")


if __name__ == "__main__":
    main()
