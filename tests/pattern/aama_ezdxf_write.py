"""A DXF-AAMA pattern set drawn with ezdxf's own API (Debian's python3-ezdxf), for
tests/pattern/aama_interop_test.cpp: a pattern file lastcut did not write, following the layer
conventions of docs/aama-dxf.md. Each piece is a BLOCK placed by an INSERT; in the block, layer 1
holds the closed cut line and the system texts ("Piece Name:", "Quantity:", "Size:", "Category:"),
layer 4 the notches, 7 the grain line, 8 an internal line, 14 a sew line. The text "Units: METRIC"
in ENTITIES says millimetres.

Two DXF versions: R12 (AC1009, what DXF-AAMA files are: POLYLINE + VERTEX; ezdxf leaves $INSUNITS
out of an R12 header, the variable came with R13, so the units text alone says mm) and R2000
(AC1015: LWPOLYLINE cut lines, and $INSUNITS 4 in the header agreeing with the text).

The notches come in both forms pattern CAD writes: the vamp's as POINTs whose angle (group 50)
points into the piece (Valentina's current export), the quarter's as short LINEs from the cut line
inward (Seamly2D, older Valentina). The lining has no grain line. The INSERTs lay the pieces out
apart from each other, and one is rotated: a reader must take each piece from its block, not from
where the INSERT puts it.

Besides the DXF the script writes, as JSON, what it drew (the reference the C++ test compares
lastcut's reading with): per piece its name, labels, quantity, cut line, its area by the shoelace
formula, the notches (position and unit direction into the piece) and the grain line.

Usage: /usr/bin/python3 aama_ezdxf_write.py R12|R2000 OUT.dxf OUT.json
"""
import json
import math
import sys

import ezdxf


def superellipse(cx, cy, a, b, n, exponent):
    """A counter-clockwise outline of n points, fuller than an ellipse for exponent < 1."""
    points = []
    for i in range(n):
        t = 2 * math.pi * i / n
        c, s = math.cos(t), math.sin(t)
        points.append((cx + a * math.copysign(abs(c) ** exponent, c), cy + b * math.copysign(abs(s) ** exponent, s)))
    return points


def shoelace(points):
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]))


def inward(points, k, centre):
    """The unit vector from outline point k towards the piece's centre (inside a convex piece)."""
    dx, dy = centre[0] - points[k][0], centre[1] - points[k][1]
    length = math.hypot(dx, dy)
    return (dx / length, dy / length)


def pieces():
    vamp = superellipse(110.0, 70.0, 110.0, 70.0, 96, 0.8)
    quarter = superellipse(0.0, 0.0, 95.5, 42.25, 64, 0.7)
    lining = [(0.0, 0.0), (180.0, 0.0), (180.0, 55.0), (120.0, 90.0), (0.0, 90.0)]
    return [
        {"name": "vamp", "size": "42", "category": "upper leather", "quantity": 2, "cut_line": vamp,
         "notches": [(k, inward(vamp, k, (110.0, 70.0))) for k in (0, 24, 48, 60)], "notch_form": "point",
         "grain_line": [(40.0, 70.0), (180.0, 70.0)], "internal": superellipse(110.0, 70.0, 100.0, 60.0, 48, 0.8),
         "sew": [(30.0, 100.0), (110.0, 120.0), (190.0, 100.0)]},
        {"name": "quarter", "size": "42", "category": "upper leather", "quantity": 4, "cut_line": quarter,
         "notches": [(k, inward(quarter, k, (0.0, 0.0))) for k in (8, 40)], "notch_form": "line",
         "grain_line": [(-40.0, -10.0), (40.0, 20.0)], "internal": None, "sew": None},
        {"name": "lining", "size": "42", "category": "lining", "quantity": 2, "cut_line": lining,
         "notches": [(1, (-math.sqrt(0.5), math.sqrt(0.5)))], "notch_form": "point", "grain_line": None, "internal": None, "sew": None},
    ]


def draw(doc, piece, at, rotation):
    block = doc.blocks.new(name=piece["name"].upper())
    if doc.dxfversion == "AC1009":
        block.add_polyline2d(piece["cut_line"], close=True, dxfattribs={"layer": "1"})
    else:
        block.add_lwpolyline(piece["cut_line"], close=True, dxfattribs={"layer": "1"})
    texts = [f"Piece Name: {piece['name']}", f"Quantity: {piece['quantity']}", f"Size: {piece['size']}",
             f"Category: {piece['category']}"]
    cx = sum(x for x, _ in piece["cut_line"]) / len(piece["cut_line"])
    cy = sum(y for _, y in piece["cut_line"]) / len(piece["cut_line"])
    for row, text in enumerate(texts):
        block.add_text(text, dxfattribs={"layer": "1", "height": 2.5, "insert": (cx, cy - 4.0 * row)})
    for k, (ux, uy) in piece["notches"]:
        x, y = piece["cut_line"][k]
        if piece["notch_form"] == "point":
            block.add_point((x, y), dxfattribs={"layer": "4", "angle": math.degrees(math.atan2(uy, ux))})
        else:
            block.add_line((x, y), (x + 3.0 * ux, y + 3.0 * uy), dxfattribs={"layer": "4"})
    if piece["grain_line"]:
        block.add_line(*piece["grain_line"], dxfattribs={"layer": "7"})
    if piece["internal"]:
        block.add_polyline2d(piece["internal"], close=True, dxfattribs={"layer": "8"})
    if piece["sew"]:
        block.add_polyline2d(piece["sew"], dxfattribs={"layer": "14"})
    doc.modelspace().add_blockref(block.name, at, dxfattribs={"layer": "1", "rotation": rotation})


def main():
    version, dxf_path, json_path = sys.argv[1], sys.argv[2], sys.argv[3]
    doc = ezdxf.new(version)
    doc.header["$INSUNITS"] = 4  # kept by R2000, dropped from R12 by ezdxf
    doc.header["$MEASUREMENT"] = 1
    for layer in ("1", "4", "7", "8", "14"):
        doc.layers.new(layer)
    drawn = pieces()
    for i, piece in enumerate(drawn):
        draw(doc, piece, (300.0 * i, 500.0), 30.0 if piece["name"] == "quarter" else 0.0)
    doc.modelspace().add_text("Units: METRIC", dxfattribs={"layer": "1", "height": 2.5, "insert": (0.0, -20.0)})
    doc.saveas(dxf_path)
    reference = []
    for piece in drawn:
        reference.append({
            "name": piece["name"], "size": piece["size"], "category": piece["category"], "quantity": piece["quantity"],
            "cut_line": piece["cut_line"], "area_mm2": shoelace(piece["cut_line"]),
            "notches": [{"at": piece["cut_line"][k], "inward": u} for k, u in piece["notches"]],
            "grain_line": piece["grain_line"]})
    with open(json_path, "w") as out:
        json.dump({"ezdxf": ezdxf.__version__, "pieces": reference}, out)


if __name__ == "__main__":
    main()
