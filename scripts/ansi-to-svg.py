#!/usr/bin/env python3
"""Turns a terminal capture with ANSI colours (`tmux capture-pane -e -p`) into an SVG image.

Used by scripts/screenshot-neovim for the README's editor screenshot. Reads the capture on
standard input and writes the SVG to standard output:

    tmux capture-pane -e -p -t SESSION | scripts/ansi-to-svg.py --columns 110 > shot.svg

Understands the SGR sequences tmux writes: the 16 basic colours, the 256-colour palette
(38;5;N / 48;5;N), 24-bit colours (38;2;R;G;B / 48;2;R;G;B), bold, italic, underline and
reverse. Every cell is placed at its own column, so the layout does not depend on the font's
exact width. Only the Python standard library is used.
"""

import argparse
import re
import sys
from xml.sax.saxutils import escape

# The 16 basic colours: a dark-background palette close to common terminal defaults.
BASIC = [
    "#1c1c1c", "#d75f5f", "#87af5f", "#d7af5f", "#5f87d7", "#af87d7", "#5fafaf", "#d0d0d0",
    "#626262", "#ff8787", "#afd787", "#ffd787", "#87afff", "#d7afff", "#87d7d7", "#ffffff",
]
DEFAULT_FG = "#d0d0d0"
DEFAULT_BG = "#1c1c1c"

CELL_WIDTH = 8.4   # px per column at font-size 14 for common monospace fonts
LINE_HEIGHT = 18   # px per row
FONT_SIZE = 14
PADDING = 10

SGR = re.compile(r"\x1b\[([0-9;:]*)m")
OTHER_ESCAPE = re.compile(r"\x1b(?:\[[0-9;?]*[A-Za-z]|\][^\x07]*\x07|[()][0-9A-Za-z])")


def palette_256(n):
    """The xterm 256-colour palette: 16 basic colours, a 6x6x6 cube, 24 greys."""
    if n < 16:
        return BASIC[n]
    if n < 232:
        n -= 16
        steps = [0, 95, 135, 175, 215, 255]
        r, g, b = steps[n // 36], steps[(n // 6) % 6], steps[n % 6]
        return f"#{r:02x}{g:02x}{b:02x}"
    grey = 8 + (n - 232) * 10
    return f"#{grey:02x}{grey:02x}{grey:02x}"


class Style:
    def __init__(self):
        self.reset()

    def reset(self):
        self.fg = None
        self.bg = None
        self.bold = False
        self.italic = False
        self.underline = False
        self.reverse = False

    def key(self):
        return (self.fg, self.bg, self.bold, self.italic, self.underline, self.reverse)

    def apply(self, params):
        codes = [int(p) if p else 0 for p in re.split(r"[;:]", params)] if params else [0]
        i = 0
        while i < len(codes):
            c = codes[i]
            if c == 0:
                self.reset()
            elif c == 1:
                self.bold = True
            elif c == 3:
                self.italic = True
            elif c in (4, 21):
                self.underline = True
            elif c == 7:
                self.reverse = True
            elif c == 22:
                self.bold = False
            elif c == 23:
                self.italic = False
            elif c == 24:
                self.underline = False
            elif c == 27:
                self.reverse = False
            elif 30 <= c <= 37:
                self.fg = BASIC[c - 30]
            elif 90 <= c <= 97:
                self.fg = BASIC[c - 90 + 8]
            elif 40 <= c <= 47:
                self.bg = BASIC[c - 40]
            elif 100 <= c <= 107:
                self.bg = BASIC[c - 100 + 8]
            elif c == 39:
                self.fg = None
            elif c == 49:
                self.bg = None
            elif c in (38, 48) and i + 1 < len(codes):
                colour = None
                if codes[i + 1] == 5 and i + 2 < len(codes):
                    colour = palette_256(codes[i + 2] % 256)
                    i += 2
                elif codes[i + 1] == 2 and i + 4 < len(codes):
                    r, g, b = (v % 256 for v in codes[i + 2:i + 5])
                    colour = f"#{r:02x}{g:02x}{b:02x}"
                    i += 4
                if c == 38:
                    self.fg = colour
                else:
                    self.bg = colour
            i += 1


def parse_line(line, style):
    """Splits one captured line into runs of (style key, text); `style` carries over lines."""
    runs = []
    pos = 0
    for match in SGR.finditer(line):
        text = OTHER_ESCAPE.sub("", line[pos:match.start()])
        if text:
            runs.append((style.key(), text))
        style.apply(match.group(1))
        pos = match.end()
    text = OTHER_ESCAPE.sub("", line[pos:])
    if text:
        runs.append((style.key(), text))
    return runs


def screen_background(lines, rows):
    """The background most cells have: the colour scheme's Normal background, if it sets one.

    tmux leaves out trailing blank cells, so the canvas must have this colour for empty rows and
    line ends to look like the rest of the screen."""
    cells = {}
    style = Style()
    for line in lines[:rows]:
        for (fg, bg, _bold, _italic, _underline, reverse), text in parse_line(line, style):
            colour = (fg or DEFAULT_FG) if reverse else (bg or DEFAULT_BG)
            cells[colour] = cells.get(colour, 0) + len(text)
    return max(cells, key=cells.get) if cells else DEFAULT_BG


def render(lines, columns, rows, title):
    width = PADDING * 2 + columns * CELL_WIDTH
    height = PADDING * 2 + rows * LINE_HEIGHT
    canvas = screen_background(lines, rows)
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height:.0f}" '
        f'viewBox="0 0 {width:.0f} {height:.0f}" role="img" aria-label="{escape(title)}">',
        f"<title>{escape(title)}</title>",
        f'<rect width="100%" height="100%" rx="6" fill="{canvas}"/>',
        f'<g font-family="\'DejaVu Sans Mono\', Menlo, Consolas, monospace" font-size="{FONT_SIZE}" '
        f'xml:space="preserve">',
    ]
    style = Style()
    for row, line in enumerate(lines[:rows]):
        col = 0
        y_top = PADDING + row * LINE_HEIGHT
        baseline = y_top + LINE_HEIGHT - 5
        texts = []
        for (fg, bg, bold, italic, underline, reverse), text in parse_line(line, style):
            fg_colour, bg_colour = fg or DEFAULT_FG, bg
            if reverse:
                fg_colour, bg_colour = bg or DEFAULT_BG, fg or DEFAULT_FG
            x = PADDING + col * CELL_WIDTH
            if bg_colour and bg_colour != canvas:
                out.append(f'<rect x="{x:.1f}" y="{y_top}" width="{len(text) * CELL_WIDTH:.1f}" '
                           f'height="{LINE_HEIGHT}" fill="{bg_colour}"/>')
            # One <text> per cell keeps every column in place whatever the font's advance width.
            attrs = f' fill="{fg_colour}"'
            if bold:
                attrs += ' font-weight="bold"'
            if italic:
                attrs += ' font-style="italic"'
            if underline:
                attrs += ' text-decoration="underline"'
            if text.strip():
                xs = " ".join(f"{PADDING + (col + i) * CELL_WIDTH:.1f}" for i in range(len(text)))
                texts.append(f'<text x="{xs}" y="{baseline}"{attrs}>{escape(text)}</text>')
            col += len(text)
        out.extend(texts)
    out.append("</g>")
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--columns", type=int, default=110)
    parser.add_argument("--rows", type=int, default=32)
    parser.add_argument("--title", default="terminal screenshot")
    args = parser.parse_args()
    lines = sys.stdin.read().split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    sys.stdout.write(render(lines, args.columns, args.rows, args.title))


if __name__ == "__main__":
    main()
