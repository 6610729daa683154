#!/usr/bin/env python3
"""An OpenEXR reader independent of the OpenEXR library, for the tests of `render -o out.exr`.

Reads a single-part scanline file (uncompressed, ZIPS or ZIP blocks; HALF, FLOAT or UINT
channels) from the file format's specification ("OpenEXR File Layout") and prints JSON:
{"width", "height", "compression", "channels": {name: [values, row-major]}}.
Usage: read_exr.py FILE
"""
import json
import struct
import sys
import zlib

COMPRESSIONS = {0: "none", 2: "zips", 3: "zip"}
LINES_PER_BLOCK = {0: 1, 2: 1, 3: 16}
SIZES = {0: 4, 1: 2, 2: 4}  # UINT, HALF, FLOAT


def attributes(data, pos):
    found = {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        type_end = data.index(b"\0", end + 1)
        kind = data[end + 1:type_end].decode()
        (size,) = struct.unpack_from("<i", data, type_end + 1)
        start = type_end + 5
        found[name] = (kind, data[start:start + size])
        pos = start + size
    return found, pos + 1


def channel_list(raw):
    channels, pos = [], 0
    while raw[pos] != 0:
        end = raw.index(b"\0", pos)
        (pixel_type,) = struct.unpack_from("<i", raw, end + 1)
        channels.append((raw[pos:end].decode(), pixel_type))
        pos = end + 1 + 16  # type, pLinear + reserved, xSampling, ySampling
    return channels


def unzip(raw, expected):
    """ZIP blocks: zlib, then the predictor and the interleaving undone."""
    t = bytearray(zlib.decompress(raw))
    if len(t) != expected:
        raise ValueError("block of %d bytes, expected %d" % (len(t), expected))
    for i in range(1, len(t)):
        t[i] = (t[i - 1] + t[i] - 128) & 0xFF
    half = (len(t) + 1) // 2
    out = bytearray(len(t))
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return bytes(out)


def read(path):
    data = open(path, "rb").read()
    magic, version = struct.unpack_from("<iI", data, 0)
    if magic != 20000630 or (version & 0xFF) != 2 or version & 0x1E00:
        raise ValueError("not a single-part scanline OpenEXR file")
    header, pos = attributes(data, 8)
    x0, y0, x1, y1 = struct.unpack("<4i", header["dataWindow"][1])
    width, height = x1 - x0 + 1, y1 - y0 + 1
    compression = header["compression"][1][0]
    if compression not in COMPRESSIONS:
        raise ValueError("compression %d not read here" % compression)
    channels = sorted(channel_list(header["channels"][1]))
    lines = LINES_PER_BLOCK[compression]
    blocks = (height + lines - 1) // lines
    offsets = struct.unpack_from("<%dQ" % blocks, data, pos)
    values = {name: [0] * (width * height) for name, _ in channels}
    for offset in offsets:
        y, size = struct.unpack_from("<ii", data, offset)
        count = min(lines, y1 + 1 - y)
        expected = count * width * sum(SIZES[t] for _, t in channels)
        raw = data[offset + 8:offset + 8 + size]
        block = raw if compression == 0 or size == expected else unzip(raw, expected)
        at = 0
        for line in range(count):  # each line: every channel's row in turn
            row = (y - y0 + line) * width
            for name, pixel_type in channels:
                code = {0: "I", 1: "e", 2: "f"}[pixel_type]
                row_values = struct.unpack_from("<%d%s" % (width, code), block, at)
                values[name][row:row + width] = row_values
                at += width * SIZES[pixel_type]
    return {"width": width, "height": height, "compression": COMPRESSIONS[compression],
            "channels": values}


if __name__ == "__main__":
    json.dump(read(sys.argv[1]), sys.stdout)
