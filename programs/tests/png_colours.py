#!/usr/bin/env python3
"""Counts the colours of a list that cover at least MIN pixels of a PNG
screenshot (8-bit RGB or RGBA, not interlaced), with the standard library only.

usage: png_colours.py SCREENSHOT MIN '#rrggbb #rrggbb ...'
prints: pixels=<all> non_white=<not white> colours=<how many of the list>"""
import struct
import sys
import zlib


def read_png(path):
    with open(path, 'rb') as f:
        data = f.read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise SystemExit(path + ': not a PNG file')
    pos, idat, header = 8, b'', None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            header = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat += body
        pos += 12 + length
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in (2, 6) or interlace:
        raise SystemExit(path + ': only 8-bit RGB or RGBA PNG without interlacing is read')
    step = 3 if colour_type == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * step
    rows, prev = [], bytearray(stride)
    at = 0
    for _ in range(height):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - step] if i >= step else 0
            b = prev[i]
            c = prev[i - step] if i >= step else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, step, rows


def main():
    path, least, colours = sys.argv[1], int(sys.argv[2]), sys.argv[3].split()
    width, height, step, rows = read_png(path)
    counts = {}
    non_white = 0
    for line in rows:
        for x in range(0, width * step, step):
            rgb = (line[x], line[x + 1], line[x + 2])
            counts[rgb] = counts.get(rgb, 0) + 1
            if rgb != (255, 255, 255):
                non_white += 1
    wanted = set(tuple(int(c[k:k + 2], 16) for k in (1, 3, 5)) for c in colours)
    found = sum(1 for c in wanted if counts.get(c, 0) >= least)
    print('pixels=%d non_white=%d colours=%d' % (width * height, non_white, found))


main()
