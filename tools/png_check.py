#!/usr/bin/env python3
"""png_check.py FILE...: fails unless each PNG is a readable, non-blank picture.

Decodes the PNG with the standard library only (zlib): 8-bit greyscale, RGB, palette
(LÖVE writes palette PNGs when a frame has few colours), grey+alpha and RGBA, with all
five row filters. A picture is blank when it has fewer than 8 distinct colours or when
fewer than 2% of its pixels differ from the most common colour.
"""
import struct
import sys
import zlib
from collections import Counter

CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def decode(path):
    with open(path, "rb") as handle:
        data = handle.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    position, chunks, palette = 8, [], None
    width = height = depth = color = None
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position:position + 8])
        body = data[position + 8:position + 8 + length]
        position += 12 + length
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
        elif kind == b"PLTE":
            palette = [tuple(body[i:i + 3]) for i in range(0, len(body), 3)]
        elif kind == b"IDAT":
            chunks.append(body)
        elif kind == b"IEND":
            break
    if depth != 8 or color not in CHANNELS:
        raise ValueError(f"unsupported PNG: bit depth {depth}, colour type {color}")
    raw = zlib.decompress(b"".join(chunks))
    step = CHANNELS[color]
    stride = width * step
    rows, previous, offset = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[offset], bytearray(raw[offset + 1:offset + 1 + stride])
        offset += 1 + stride
        for i in range(stride):
            left = line[i - step] if i >= step else 0
            up = previous[i]
            corner = previous[i - step] if i >= step else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + ((left + up) >> 1)) & 255
            elif kind == 4:
                line[i] = (line[i] + paeth(left, up, corner)) & 255
        rows.append(bytes(line))
        previous = line
    pixels = []
    for line in rows:
        for i in range(0, stride, step):
            value = tuple(line[i:i + step])
            if color == 3:
                value = palette[value[0]]
            pixels.append(value[:3] if color in (2, 3, 6) else value[:1])
    return width, height, pixels


def main(paths):
    failed = 0
    for path in paths:
        try:
            width, height, pixels = decode(path)
        except (OSError, ValueError, zlib.error, struct.error) as error:
            print(f"{path}: unreadable: {error}")
            failed += 1
            continue
        counts = Counter(pixels)
        _, most = counts.most_common(1)[0]
        other = 1 - most / len(pixels)
        verdict = "ok" if len(counts) >= 8 and other >= 0.02 else "BLANK"
        print(f"{path}: {width}x{height}, {len(counts)} colours, "
              f"{other:.1%} off the background: {verdict}")
        failed += verdict != "ok"
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
