#!/usr/bin/env python3
"""Writes the texture fuzz target's seeds into the directory given: tiny PNG, JPEG, HDR and EXR
files covering the colour types rtc's decoders meet, and the course textures scaled down. Each
seed is one byte choosing the extension (0 png, 1 jpg, 2 hdr, 3 exr) followed by the file."""
import io
import math
import os
import struct
import sys

from PIL import Image

HERE = os.path.dirname(os.path.abspath(__file__))
TEXTURES = os.path.join(HERE, '..', 'tests', 'data', 'course', 'textures')


def ramp(mode, w, h):
    im = Image.new('RGB', (w, h))
    for y in range(h):
        for x in range(w):
            im.putpixel((x, y), ((x * 255) // max(w - 1, 1), (y * 255) // max(h - 1, 1), ((x + y) * 40) % 256))
    return im if mode == 'RGB' else im.convert(mode)


def encoded(im, fmt, **kw):
    b = io.BytesIO()
    im.save(b, fmt, **kw)
    return b.getvalue()


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    f, e = math.frexp(m)
    s = f * 256.0 / m
    return bytes([int(r * s), int(g * s), int(b * s), e + 128])


def hdr(w, h):
    """Radiance RGBE with flat (not run-length) scanlines."""
    head = b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n' % (h, w)
    return head + b''.join(rgbe(0.1 + x, 0.5 * y, 2.0) for y in range(h) for x in range(w))


def exr(w, h, ptype):
    """Single-part scanline OpenEXR, no compression, channels B, G, R (1 = half, 2 = float)."""
    def attr(name, typ, data):
        return name.encode() + b'\0' + typ.encode() + b'\0' + struct.pack('<i', len(data)) + data
    chans = b''.join(c.encode() + b'\0' + struct.pack('<iB3xii', ptype, 0, 1, 1) for c in 'BGR') + b'\0'
    head = struct.pack('<ii', 20000630, 2)
    head += attr('channels', 'chlist', chans)
    head += attr('compression', 'compression', b'\0')
    head += attr('dataWindow', 'box2i', struct.pack('<iiii', 0, 0, w - 1, h - 1))
    head += attr('displayWindow', 'box2i', struct.pack('<iiii', 0, 0, w - 1, h - 1))
    head += attr('lineOrder', 'lineOrder', b'\0')
    head += attr('pixelAspectRatio', 'float', struct.pack('<f', 1.0))
    head += attr('screenWindowCenter', 'v2f', struct.pack('<ff', 0, 0))
    head += attr('screenWindowWidth', 'float', struct.pack('<f', 1.0))
    head += b'\0'
    blocks = []
    for y in range(h):
        row = b''.join(struct.pack('<e' if ptype == 1 else '<f', (x + 1) * 0.25 + c * 0.1 + y)
                       for c in range(3) for x in range(w))
        blocks.append(struct.pack('<ii', y, len(row)) + row)
    offsets, pos = [], len(head) + 8 * h
    for b in blocks:
        offsets.append(pos)
        pos += len(b)
    return head + b''.join(struct.pack('<Q', o) for o in offsets) + b''.join(blocks)


def main(out):
    os.makedirs(out, exist_ok=True)
    seeds = {
        'png_rgb_4x4': (0, encoded(ramp('RGB', 4, 4), 'PNG')),
        'png_rgba_3x2': (0, encoded(ramp('RGBA', 3, 2), 'PNG')),
        'png_gray_5x1': (0, encoded(ramp('L', 5, 1), 'PNG')),
        'png_la_2x2': (0, encoded(ramp('LA', 2, 2), 'PNG')),
        'png_palette_4x4': (0, encoded(ramp('P', 4, 4), 'PNG')),
        'png_1bit_8x2': (0, encoded(ramp('1', 8, 2), 'PNG')),
        'png_gray16_2x2': (0, encoded(ramp('L', 2, 2).convert('I;16'), 'PNG')),
        'png_optimized_8x8': (0, encoded(ramp('RGB', 8, 8), 'PNG', optimize=True)),
        'png_bluegrid': (0, open(os.path.join(TEXTURES, 'bluegrid.png'), 'rb').read()),
        'jpg_rgb_8x8': (1, encoded(ramp('RGB', 8, 8), 'JPEG', quality=50)),
        'jpg_gray_8x8': (1, encoded(ramp('L', 8, 8), 'JPEG', quality=50)),
        'jpg_progressive_16x8': (1, encoded(ramp('RGB', 16, 8), 'JPEG', quality=40, progressive=True)),
        'jpg_cmyk_8x8': (1, encoded(ramp('CMYK', 8, 8), 'JPEG', quality=50)),
        'jpg_earth_16x8': (1, encoded(Image.open(os.path.join(TEXTURES, 'earthmap1k.jpg')).resize((16, 8)), 'JPEG', quality=60)),
        'jpg_earthbump_16x8': (1, encoded(Image.open(os.path.join(TEXTURES, 'earthbump1k.jpg')).resize((16, 8)), 'JPEG', quality=60)),
        'hdr_rgbe_4x3': (2, hdr(4, 3)),
        'exr_half_3x2': (3, exr(3, 2, 1)),
        'exr_float_2x2': (3, exr(2, 2, 2)),
    }
    for name, (kind, data) in seeds.items():
        with open(os.path.join(out, name), 'wb') as f:
            f.write(bytes([kind]) + data)


if __name__ == '__main__':
    main(sys.argv[1])
