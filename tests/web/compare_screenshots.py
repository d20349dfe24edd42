#!/usr/bin/env python3
"""compare_screenshots.py: whether two screenshots of the same window state (the desktop's and the web page's) show
the same picture within a tolerance, with Python's standard library only.

    compare_screenshots.py A.png B.png [--threshold N] [--tile PX] [--tile-share PERCENT] [--max-tiles K]
                           [--ignore X,Y,W,H ...] [--diff OUT.png]

The two renderers (llvmpipe on the desktop, SwiftShader in the page) round and antialias a little differently, so
the images are never equal: their differences are thin (an edge a pixel to one side), spread over the picture. What
a person would call a different picture (a table, a mesh, a line of text missing or moved) is a patch of differing
pixels. So a pixel differs when one of its channels differs by more than --threshold (of 255, default 64); a tile of
--tile x --tile pixels (32) differs when more than --tile-share percent (5) of its pixels differ; and the images
match when at most --max-tiles tiles (4) differ. --ignore leaves out a rectangle (in pixels) that is meant to differ,
such as the status bar's frame time. Images of different sizes never match. --diff writes image A dimmed to a
quarter, with the differing pixels in red and the differing tiles outlined in yellow, to look at. Exit status: 0
when they match, 1 when not, 2 when an image cannot be read.
"""
import argparse
import struct
import sys
import zlib

CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # PNG colour type -> channels (grey, RGB, grey + alpha, RGBA)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def unfilter(rows, stride, bpp):
    """The raw bytes of each scanline, the PNG filters undone."""
    previous = bytearray(stride)
    out = []
    for row in rows:
        kind, line = row[0], bytearray(row[1:])
        if kind == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif kind == 2:
            line = bytearray((x + y) & 255 for x, y in zip(line, previous))
        elif kind == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                up_left = previous[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + paeth(left, previous[i], up_left)) & 255
        out.append(line)
        previous = line
    return out


def read_png(path):
    """(width, height, rows of RGB bytes) of an 8-bit, non-interlaced PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + " is no PNG")
    at, idat, header = 8, [], None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in CHANNELS or interlace:
        raise ValueError("%s: only 8-bit, non-interlaced grey or RGB(A) PNGs are read here" % path)
    channels = CHANNELS[colour]
    stride = width * channels
    raw = zlib.decompress(b"".join(idat))
    rows = unfilter([raw[y * (stride + 1):(y + 1) * (stride + 1)] for y in range(height)], stride, channels)
    if channels == 3:
        return width, height, rows
    rgb = []
    for line in rows:
        if channels == 4:
            out = bytearray(width * 3)
            out[0::3], out[1::3], out[2::3] = line[0::4], line[1::4], line[2::4]
        else:
            grey = line[0::channels]
            out = bytearray(width * 3)
            out[0::3] = out[1::3] = out[2::3] = grey
        rgb.append(out)
    return width, height, rgb


def write_png(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    raw = b"".join(b"\0" + bytes(row) for row in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def differing_pixels(rows_a, rows_b, threshold, ignored):
    """A mask per row of the pixels with a channel differing by more than `threshold`, outside the ignored
    rectangles (x, y, width, height)."""
    masks = []
    for y, (line_a, line_b) in enumerate(zip(rows_a, rows_b)):
        far = [abs(p - q) > threshold for p, q in zip(line_a, line_b)]
        mask = [far[i] or far[i + 1] or far[i + 2] for i in range(0, len(far), 3)]
        for x, top, width, height in ignored:
            if top <= y < top + height:
                mask[x:x + width] = [False] * len(mask[x:x + width])
        masks.append(mask)
    return masks


def differing_tiles(masks, tile, share):
    """The (column, row) of each tile in which more than `share` percent of the pixels differ."""
    counts = {}
    for y, mask in enumerate(masks):
        for x, far in enumerate(mask):
            if far:
                key = (x // tile, y // tile)
                counts[key] = counts.get(key, 0) + 1
    return sorted(key for key, count in counts.items() if count > share / 100.0 * tile * tile)


def diff_image(rows_a, masks, tiles, tile):
    out = []
    for line, mask in zip(rows_a, masks):
        row = bytearray(value >> 2 for value in line)
        for x, far in enumerate(mask):
            if far:
                row[3 * x:3 * x + 3] = b"\xff\x00\x00"
        out.append(row)
    height, width = len(out), len(out[0]) // 3
    for column, row in tiles:
        x0, y0 = column * tile, row * tile
        x1, y1 = min(x0 + tile, width) - 1, min(y0 + tile, height) - 1
        for x in range(x0, x1 + 1):
            out[y0][3 * x:3 * x + 3] = out[y1][3 * x:3 * x + 3] = b"\xff\xff\x00"
        for y in range(y0, y1 + 1):
            out[y][3 * x0:3 * x0 + 3] = out[y][3 * x1:3 * x1 + 3] = b"\xff\xff\x00"
    return out


def rectangle(text):
    values = [int(v) for v in text.split(",")]
    if len(values) != 4:
        raise argparse.ArgumentTypeError("a rectangle is X,Y,W,H")
    return tuple(values)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--threshold", type=int, default=64)
    parser.add_argument("--tile", type=int, default=32)
    parser.add_argument("--tile-share", type=float, default=5.0)
    parser.add_argument("--max-tiles", type=int, default=4)
    parser.add_argument("--ignore", type=rectangle, nargs="+", default=[])
    parser.add_argument("--diff")
    args = parser.parse_args()
    try:
        width, height, rows_a = read_png(args.a)
        width_b, height_b, rows_b = read_png(args.b)
    except (OSError, ValueError, zlib.error, TypeError, struct.error) as e:
        print("compare_screenshots: %s" % e)
        return 2
    if (width, height) != (width_b, height_b):
        print("compare_screenshots: %s is %dx%d, %s %dx%d" % (args.a, width, height, args.b, width_b, height_b))
        return 1
    masks = differing_pixels(rows_a, rows_b, args.threshold, args.ignore)
    tiles = differing_tiles(masks, args.tile, args.tile_share)
    if args.diff:
        write_png(args.diff, width, height, diff_image(rows_a, masks, tiles, args.tile))
    count = sum(sum(mask) for mask in masks)
    matched = len(tiles) <= args.max_tiles
    print("compare_screenshots: %d of %d pixels (%.2f%%) differ by more than %d; %d tiles of %dx%d have more than "
          "%g%% of theirs differing (at most %d may): %s" %
          (count, width * height, 100.0 * count / (width * height), args.threshold, len(tiles), args.tile,
           args.tile, args.tile_share, args.max_tiles, "they match" if matched else "they differ"))
    return 0 if matched else 1


if __name__ == "__main__":
    sys.exit(main())
