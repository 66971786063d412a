#!/usr/bin/env python3
"""Draws the device symbols of the three shipped cards.

Writes descriptions/symbols/md810dp.png, 9kdp1.png and mv810-pnet02.png:
70 x 40 pixels, the size engineering tools show a device symbol at, drawn
only in the 16 colours of gsdc's bitmap palette (src/symbol.rs, PALETTE), so
gsdc converts them to the GSD/GSDML bitmap without changing a pixel.

Each symbol is a card seen from above: the green board with its bus connector
on the left edge (a 9-pin D-sub for PROFIBUS DP, two RJ45 jacks for PROFINET),
the card's name in a 5x7 pixel font and the bus in a 3x5 one. These are
simple drawings made for the repository, not the vendors' pictures.

Python 3.11 standard library only; the PNGs are written byte for byte the
same on every run (no time or text chunks).

    python3 scripts/draw-symbols.py            # writes into descriptions/symbols/
    python3 scripts/draw-symbols.py OUT_DIR
"""

import pathlib
import struct
import sys
import zlib

WIDTH, HEIGHT = 70, 40

# src/symbol.rs PALETTE, same order: the PNG's palette indexes are the
# bitmap's.
PALETTE = [
    (0x00, 0x00, 0x00), (0x80, 0x00, 0x00), (0x00, 0x80, 0x00), (0x80, 0x80, 0x00),
    (0x00, 0x00, 0x80), (0x80, 0x00, 0x80), (0x00, 0x80, 0x80), (0xC0, 0xC0, 0xC0),
    (0x80, 0x80, 0x80), (0xFF, 0x00, 0x00), (0x00, 0xFF, 0x00), (0xFF, 0xFF, 0x00),
    (0x00, 0x00, 0xFF), (0xFF, 0x00, 0xFF), (0x00, 0xFF, 0xFF), (0xFF, 0xFF, 0xFF),
]
BLACK, GREEN, PURPLE, SILVER, GREY, LIME, YELLOW, WHITE = 0, 2, 5, 7, 8, 10, 11, 15

# 5x7 glyphs for the card names, 3x5 glyphs for the bus names (N is 4 wide).
BIG_FONT = {
    "0": [".XXX.", "X...X", "X..XX", "X.X.X", "XX..X", "X...X", ".XXX."],
    "1": ["..X..", ".XX..", "..X..", "..X..", "..X..", "..X..", ".XXX."],
    "8": [".XXX.", "X...X", "X...X", ".XXX.", "X...X", "X...X", ".XXX."],
    "9": [".XXX.", "X...X", "X...X", ".XXXX", "....X", "...X.", ".XX.."],
    "D": ["XXXX.", "X...X", "X...X", "X...X", "X...X", "X...X", "XXXX."],
    "K": ["X...X", "X..X.", "X.X..", "XX...", "X.X..", "X..X.", "X...X"],
    "M": ["X...X", "XX.XX", "X.X.X", "X.X.X", "X...X", "X...X", "X...X"],
    "P": ["XXXX.", "X...X", "X...X", "XXXX.", "X....", "X....", "X...."],
    "V": ["X...X", "X...X", "X...X", "X...X", "X...X", ".X.X.", "..X.."],
}
SMALL_FONT = {
    " ": ["...", "...", "...", "...", "..."],
    "B": ["XX.", "X.X", "XX.", "X.X", "XX."],
    "D": ["XX.", "X.X", "X.X", "X.X", "XX."],
    "E": ["XXX", "X..", "XX.", "X..", "XXX"],
    "F": ["XXX", "X..", "XX.", "X..", "X.."],
    "I": ["XXX", ".X.", ".X.", ".X.", "XXX"],
    "N": ["X..X", "XX.X", "X.XX", "X..X", "X..X"],  # 3 wide would read as "n"
    "O": [".X.", "X.X", "X.X", "X.X", ".X."],
    "P": ["XX.", "X.X", "XX.", "X..", "X.."],
    "R": ["XX.", "X.X", "XX.", "X.X", "X.X"],
    "S": [".XX", "X..", ".X.", "..X", "XX."],
    "T": ["XXX", ".X.", ".X.", ".X.", ".X."],
    "U": ["X.X", "X.X", "X.X", "X.X", "XXX"],
}


class Canvas:
    def __init__(self):
        self.pixels = [[WHITE] * WIDTH for _ in range(HEIGHT)]

    def fill(self, x0, y0, x1, y1, colour):
        """Fills the rectangle from (x0, y0) to (x1, y1), both included."""
        for y in range(y0, y1 + 1):
            for x in range(x0, x1 + 1):
                self.pixels[y][x] = colour

    def box(self, x0, y0, x1, y1, inside, outline=BLACK):
        self.fill(x0, y0, x1, y1, outline)
        self.fill(x0 + 1, y0 + 1, x1 - 1, y1 - 1, inside)

    def text(self, x, y, string, font, colour):
        for char in string:
            glyph = font[char]
            for dy, row in enumerate(glyph):
                for dx, cell in enumerate(row):
                    if cell == "X":
                        self.pixels[y + dy][x + dx] = colour
            x += len(glyph[0]) + 1


def board(canvas, name, bus):
    """The board, to the right of the connector, with its two lines of text."""
    canvas.box(15, 3, 68, 36, GREEN)
    canvas.text(20, 8, name, BIG_FONT, WHITE)
    # A chip beside the name, and the row of pins of the drive-side connector.
    canvas.box(54, 7, 64, 15, BLACK, outline=GREY)
    for x in range(20, 65, 3):
        canvas.fill(x, 19, x + 1, 20, YELLOW)
    canvas.text(20, 27, bus, SMALL_FONT, YELLOW)


def d_sub(canvas):
    """A 9-pin D-sub on the left edge: 5 pins over 4, in PROFIBUS purple."""
    canvas.box(3, 8, 15, 31, SILVER)
    canvas.fill(4, 5, 6, 7, GREY)  # screws of the bracket
    canvas.fill(4, 32, 6, 34, GREY)
    canvas.box(5, 11, 12, 28, PURPLE)
    for y in (13, 16, 19, 22, 25):
        canvas.fill(7, y, 7, y + 1, YELLOW)
    for y in (14, 17, 20, 23):
        canvas.fill(10, y + 1, 10, y + 2, YELLOW)


def rj45_pair(canvas):
    """Two RJ45 jacks on the left edge, each with its link LED."""
    for top in (5, 21):
        canvas.box(2, top, 15, top + 13, SILVER)
        canvas.fill(4, top + 3, 11, top + 9, BLACK)
        canvas.fill(6, top + 10, 9, top + 11, BLACK)  # the latch notch
        canvas.fill(13, top + 2, 13, top + 4, LIME)
        canvas.fill(13, top + 8, 13, top + 10, YELLOW)


def png(pixels):
    """An 8-bit palette PNG of the pixels, with gsdc's palette."""

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", WIDTH, HEIGHT, 8, 3, 0, 0, 0)
    palette = bytes(sample for colour in PALETTE for sample in colour)
    # Filter type 0 (none) before every row.
    raw = b"".join(b"\x00" + bytes(row) for row in pixels)
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", header)
        + chunk(b"PLTE", palette)
        + chunk(b"IDAT", zlib.compress(raw, 9))
        + chunk(b"IEND", b"")
    )


def symbol(name, bus, connector):
    canvas = Canvas()
    board(canvas, name, bus)
    connector(canvas)
    return png(canvas.pixels)


SYMBOLS = {
    "md810dp.png": ("MD810", "PROFIBUS DP", d_sub),
    "9kdp1.png": ("9KDP1", "PROFIBUS DP", d_sub),
    "mv810-pnet02.png": ("MV810", "PROFINET", rj45_pair),
}


def main():
    repository = pathlib.Path(__file__).resolve().parent.parent
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else repository / "descriptions" / "symbols"
    out.mkdir(parents=True, exist_ok=True)
    for file_name, (name, bus, connector) in SYMBOLS.items():
        (out / file_name).write_bytes(symbol(name, bus, connector))
        print(out / file_name)


if __name__ == "__main__":
    main()
