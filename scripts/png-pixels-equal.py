#!/usr/bin/env python3
"""png-pixels-equal.py A.png B.png: exit status 0 if the two PNGs decode to the same 8-bit RGB
pixels (and size), 1 if not. Reads 8-bit RGB and indexed (palette) PNGs, non-interlaced: what
`microtrace render` writes now (indexed) and wrote before (RGB). Only the standard library, so
scripts/bench-desktop.sh can compare the baseline's image with the current one's pixel for
pixel although the files differ byte for byte."""
import struct, sys, zlib

def rgb_pixels(path):
    """The 8-bit RGB pixels of an 8-bit RGB or indexed PNG (non-interlaced), rows top first."""
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError(path + ': not a PNG')
    at, idat, palette = 8, [], None
    while at < len(data):
        length, kind = struct.unpack('>I4s', data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        at += 12 + length
        if kind == b'IHDR':
            width, height, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', body)
        elif kind == b'PLTE':
            palette = body
        elif kind == b'IDAT':
            idat.append(body)
    if depth != 8 or interlace or colour not in (2, 3):
        raise ValueError(path + ': only 8-bit RGB or indexed, non-interlaced PNGs')
    step = 3 if colour == 2 else 1
    stride = width * step
    raw = zlib.decompress(b''.join(idat))
    previous, rows = bytearray(stride), []
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - step] if i >= step else 0
            up = previous[i]
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                corner = previous[i - step] if i >= step else 0
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append(bytes(line))
        previous = line
    pixels = b''.join(rows)
    if colour == 3:
        pixels = b''.join(palette[3 * index:3 * index + 3] for index in pixels)
    return width, height, pixels

first, second = (rgb_pixels(path) for path in sys.argv[1:3])
sys.exit(0 if first == second else 1)
