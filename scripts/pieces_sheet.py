#!/usr/bin/env python3
"""One sheet of a style's pieces, as `lastcut style pieces` wrote them (docs/pictures/*-pieces-*.png).

    python3 scripts/pieces_sheet.py OUT_DIR SHEET.svg [--columns 2]
    rsvg-convert -w 1220 SHEET.svg -o SHEET.png        # Debian's librsvg2-bin

Reads OUT_DIR/pieces.json and each piece's PIECE.svg, and places the pieces at one scale (true mm) in a
grid, each under a caption: its name and, per kind of edge, the allowance it carries (from pieces.json).
Python's standard library only; the pieces' own SVGs are nested unchanged.
"""
import argparse
import json
import re
import sys
from pathlib import Path
from xml.sax.saxutils import escape

CAPTION_MM = 9.0
GAP_MM = 8.0


def svg_size_mm(text):
    """The width and height of a piece SVG's root, in mm."""
    root = re.search(r"<svg\b[^>]*>", text).group(0)
    width = float(re.search(r'width="([\d.]+)mm"', root).group(1))
    height = float(re.search(r'height="([\d.]+)mm"', root).group(1))
    return width, height


def caption(piece):
    """'vamp: feather line 18, line apron 8, top edge 5 mm': each edge kind once, with its allowance."""
    seen = []
    for edge in piece["edges"]:
        item = "%s %g" % (edge["on"], edge["allowance_mm"])
        if item not in seen:
            seen.append(item)
    return "%s: %s mm" % (piece["name"], ", ".join(seen))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir", type=Path)
    parser.add_argument("sheet", type=Path)
    parser.add_argument("--columns", type=int, default=2)
    args = parser.parse_args()

    report = json.loads((args.out_dir / "pieces.json").read_text())
    cells = []
    for piece in report["pieces"]:
        text = (args.out_dir / (Path(piece["file"]).stem + ".svg")).read_text()
        body = re.sub(r"<\?xml[^>]*\?>\s*", "", text)
        cells.append((caption(piece), body, svg_size_mm(text)))

    columns = max(1, args.columns)
    rows = [cells[i:i + columns] for i in range(0, len(cells), columns)]
    column_width = [max(row[c][2][0] for row in rows if c < len(row)) for c in range(columns)]
    parts, y = [], GAP_MM
    for row in rows:
        x = GAP_MM
        for c, (title, body, (width, height)) in enumerate(row):
            parts.append('<text x="%.1f" y="%.1f" font-size="5">%s</text>' % (x, y + 5, escape(title)))
            # The piece's own <svg> nested where it goes, its size in the sheet's units (mm), not in CSS mm.
            root = re.search(r"<svg\b[^>]*>", body).group(0)
            placed = re.sub(r'(width|height)="([\d.]+)mm"', r'\1="\2"', root).replace(
                "<svg", '<svg x="%.1f" y="%.1f"' % (x, y + CAPTION_MM), 1)
            parts.append(body.replace(root, placed, 1))
            x += column_width[c] + GAP_MM
        y += CAPTION_MM + max(cell[2][1] for cell in row) + GAP_MM
    width = GAP_MM + sum(w + GAP_MM for w in column_width)
    sheet = ('<?xml version="1.0" encoding="UTF-8"?>\n'
             '<svg xmlns="http://www.w3.org/2000/svg" width="%.1fmm" height="%.1fmm" viewBox="0 0 %.1f %.1f" '
             'font-family="sans-serif">\n<rect width="100%%" height="100%%" fill="white"/>\n%s\n</svg>\n'
             % (width, y, width, y, "\n".join(parts)))
    args.sheet.write_text(sheet)
    return 0


if __name__ == "__main__":
    sys.exit(main())
