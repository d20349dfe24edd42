#!/usr/bin/env python3
"""compare_writeups.py DESKTOP.html PAGE.html: whether the page's write-up (File > Write-up, downloaded) is the
desktop's (`meshedit writeup`) for the same files: the same text, word for word, once each page's folder name is put
aside and each picture is put aside as a PNG of the write-up's size (SwiftShader and llvmpipe draw a few pixels apart).
Prints the first difference; exit status 0 the same, 1 not."""
import base64
import difflib
import re
import struct
import sys

PICTURE = re.compile(r'src="data:image/png;base64,([A-Za-z0-9+/=]*)"')


def normalized(path):
    text = open(path, encoding="utf-8").read()
    sizes = []
    for encoded in PICTURE.findall(text):
        png = base64.b64decode(encoded)
        if png[:8] != b"\x89PNG\r\n\x1a\n":
            sys.exit(f"compare_writeups: {path}: a picture that is not a PNG")
        sizes.append(struct.unpack(">II", png[16:24]))
    text = PICTURE.sub('src="PICTURE"', text)
    folder = re.search(r"<h1>Write-up: ([^<]*)</h1>", text)
    if not folder:
        sys.exit(f"compare_writeups: {path}: no <h1>Write-up: FOLDER</h1>")
    return text.replace(folder.group(1), "FOLDER"), sizes


def main():
    desktop, desktop_sizes = normalized(sys.argv[1])
    page, page_sizes = normalized(sys.argv[2])
    if desktop_sizes != page_sizes:
        print(f"compare_writeups: pictures differ: desktop {desktop_sizes}, page {page_sizes}")
        return 1
    if desktop != page:
        diff = difflib.unified_diff(desktop.split("\n"), page.split("\n"), "desktop", "page", lineterm="", n=1)
        print("compare_writeups: the texts differ:\n" + "\n".join(list(diff)[:40]))
        return 1
    print(f"compare_writeups: the same write-up, {len(page_sizes)} pictures")
    return 0


if __name__ == "__main__":
    sys.exit(main())
