# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Compares what ParaView read (render_series.py --summary) with what was
written (write_example_series), and checks that the PNGs show something.

    python3 check_render.py EXPECTED_JSON SUMMARY_JSON
"""

import json
import struct
import sys
import zlib


def png_pixels(path):
    """Decodes an 8-bit RGB/RGBA PNG (what ParaView writes) with the standard library."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + " is not a PNG")
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6):
                raise ValueError("%s: unsupported PNG depth %d / colour type %d" % (path, depth, colour))
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        filt = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            upleft = previous[i - channels] if i >= channels else 0
            if filt == 1:
                line[i] = (line[i] + left) & 255
            elif filt == 2:
                line[i] = (line[i] + up) & 255
            elif filt == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif filt == 4:
                p = left + up - upleft
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - upleft)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else upleft)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def main(expected_path, summary_path):
    expected = json.load(open(expected_path))
    summary = json.load(open(summary_path))
    errors = []
    got, want = summary["steps"], expected["steps"]
    if len(got) != len(want):
        errors.append("ParaView read %d steps, %d were written" % (len(got), len(want)))
    for i, (g, w) in enumerate(zip(got, want)):
        for key in ("cells", "points"):
            if g[key] != w[key]:
                errors.append("step %d: ParaView read %d %s, %d were written" % (i, g[key], key, w[key]))
        if abs(g["time"] - w["time"]) > 1e-12:
            errors.append("step %d: time %r, expected %r" % (i, g["time"], w["time"]))
        missing = sorted(set(expected["cell_arrays"]) - set(g["cell_arrays"]))
        if missing:
            errors.append("step %d: cell arrays missing in ParaView: %s" % (i, ", ".join(missing)))
        width, height, channels, rows = png_pixels(g["png"])
        colours = {row[x:x + 3] for row in rows[::4] for x in range(0, width * channels, 4 * channels)}
        background = sum(1 for row in rows for x in range(0, width * channels, channels)
                         if row[x:x + 3] == b"\xff\xff\xff")
        covered = 1.0 - background / float(width * height)
        print("step %d: %d cells, %d points, %dx%d PNG, %d colours (sampled), %.0f%% non-background"
              % (i, g["cells"], g["points"], width, height, len(colours), 100 * covered))
        if len(colours) < 8:
            errors.append("step %d: %s has only %d colours: nothing was drawn" % (i, g["png"], len(colours)))
        if covered < 0.10:
            errors.append("step %d: %s is %.1f%% background: the tissue is missing" % (i, g["png"], 100 * (1 - covered)))
    for e in errors:
        print("FAIL: " + e)
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
