#!/usr/bin/env python3
"""Writes height_field_map.png, the 16-bit greyscale height map of the `height_field` twin
(and of rtc's height-field tests): 33 x 25 pixels, a ridge, a crater and a tall peak near
pixel (0, 0), so the image's orientation shows. Standard library only (zlib, struct):

    python3 tests/data/pov_twins/height_field_map.py
"""
import math
import struct
import zlib
from pathlib import Path

W, H = 33, 25


def height(i, j):
    """Grey in [0, 1] of pixel (i, j), j from the top."""
    x, y = i / (W - 1), j / (H - 1)
    ridge = 0.35 * math.exp(-((x - 0.6 - 0.2 * y) ** 2) / 0.01)
    peak = 0.55 * math.exp(-((x - 0.15) ** 2 + (y - 0.2) ** 2) / 0.012)
    r = math.hypot(x - 0.7, y - 0.75)
    crater = 0.25 * math.exp(-((r - 0.15) ** 2) / 0.003)
    return min(1.0, 0.08 + 0.1 * x + ridge + peak + crater)


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


rows = b"".join(
    b"\x00" + b"".join(struct.pack(">H", round(height(i, j) * 65535)) for i in range(W))
    for j in range(H)
)
png = (
    b"\x89PNG\r\n\x1a\n"
    + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 16, 0, 0, 0, 0))
    + chunk(b"IDAT", zlib.compress(rows, 9))
    + chunk(b"IEND", b"")
)
(Path(__file__).parent / "height_field_map.png").write_bytes(png)
