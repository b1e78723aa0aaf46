#!/usr/bin/env python3
"""Crops 8-bit RGB/RGBA PNG files, enlarges the crops without smoothing (each pixel a k x k
block, so sampling artefacts stay visible) and lays them side by side: the close-ups in
docs/antialiasing.md.

usage: crop-png.py OUT.png X Y W H SCALE IN1.png [IN2.png ...]
Standard library only (zlib), so it runs wherever raylab builds."""

import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG file")
    pos, idat, width, height, channels = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                sys.exit(f"{path}: only 8-bit RGB/RGBA non-interlaced PNG is supported")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return rows


def write_png(path, rows):
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(v for px in row for v in px) for row in rows)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)


def main():
    if len(sys.argv) < 8:
        sys.exit(__doc__)
    out = sys.argv[1]
    x, y, w, h, k = (int(v) for v in sys.argv[2:7])
    gap = [(255, 255, 255)] * 4
    strip = [[] for _ in range(h * k)]
    for n, path in enumerate(sys.argv[7:]):
        rows = read_png(path)
        if y + h > len(rows) or x + w > len(rows[0]):
            sys.exit(f"{path}: the crop lies outside the {len(rows[0])}x{len(rows)} image")
        for j in range(h * k):
            src = rows[y + j // k]
            strip[j] += (gap if n else []) + [src[x + i // k] for i in range(w * k)]
    write_png(out, strip)


if __name__ == "__main__":
    main()
