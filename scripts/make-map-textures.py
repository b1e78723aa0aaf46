#!/usr/bin/python3
"""Writes the two maps of scenes/maps.json into scenes/textures/ (run once; the PNGs are kept):

- tiles-normal.png: a tangent-space normal map (OpenGL's convention) of 4 x 4 square tiles with
  bevelled edges, 8-bit linear values;
- ripples-height.png: a grey height map of circular ripples around the centre.

Pure Python (zlib for the PNG), so that it needs nothing beyond Debian's interpreter."""
import math
import struct
import sys
import zlib
from pathlib import Path


def write_png(path, width, height, rgb_rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rgb_rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    Path(path).write_bytes(png)


def code(x):
    return max(0, min(255, round((x * 0.5 + 0.5) * 255)))


def tiles(size=128, count=4, bevel=0.12):
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            # Position inside its tile in [0, 1); v runs up the image, as raylab's texture convention.
            fu = (x + 0.5) / size * count % 1.0
            fv = (1.0 - (y + 0.5) / size) * count % 1.0
            nx = ny = 0.0
            slope = 0.8
            if fu < bevel:
                nx = -slope
            elif fu > 1 - bevel:
                nx = slope
            if fv < bevel:
                ny = -slope
            elif fv > 1 - bevel:
                ny = slope
            length = math.sqrt(nx * nx + ny * ny + 1.0)
            row += [code(nx / length), code(ny / length), code(1.0 / length)]
        rows.append(row)
    return rows


def ripples(size=128, waves=6.0):
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            r = math.hypot((x + 0.5) / size - 0.5, (y + 0.5) / size - 0.5)
            h = 0.5 + 0.5 * math.cos(2 * math.pi * waves * r)
            row += [round(h * 255)] * 3
        rows.append(row)
    return rows


if __name__ == "__main__":
    out = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "scenes" / "textures")
    write_png(out / "tiles-normal.png", 128, 128, tiles())
    write_png(out / "ripples-height.png", 128, 128, ripples())
