"""An independent reading of a DXF-AAMA file with ezdxf (Debian's python3-ezdxf), for
tests/pattern/aama_independent_readers_test.cpp: runs ezdxf's audit and prints, as JSON, what ezdxf
finds in each block an INSERT places: closed and open polylines on layer 1 with their vertex counts,
POINTs on layer 4 with their angle, LINEs on layer 7, polylines on layers 8 and 14, the layer-1
texts, the cut line's bounding box where the INSERT puts it, and the area each closed layer-1
polyline encloses (shoelace formula over ezdxf's vertices, in the block's units). The C++ tests
compare that with the pieces they wrote or read.

The audit's errors are reported, and its fixes but one kind: ezdxf 0.18 (bookworm) "fixes" the
SEQEND of every POLYLINE inside a block of an R12 file by deleting it for an invalid owner handle
(#None). It does so for R12 files it wrote itself (ezdxf.new("R12"), a polyline in a block, saved
and read back): its loader gives such a SEQEND no owner, nothing in the file can. Every other fix
(an INSERT of an undefined block, ...) is reported.

Usage: python3 aama_ezdxf_report.py FILE.dxf REPORT.json
"""
import json
import sys

import ezdxf
from ezdxf.audit import AuditError


def polyline_points(entity):
    if entity.dxftype() == "LWPOLYLINE":
        return [(p[0], p[1]) for p in entity.get_points("xy")]
    return [(v.dxf.location.x, v.dxf.location.y) for v in entity.vertices]


def shoelace(points):
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]))


def block_report(block, at):
    report = {"closed_cut_lines": [], "cut_areas": [], "open_cut_lines": 0, "notch_points": [], "notch_lines": 0,
              "grain_lines": [], "internal_lines": [], "sew_lines": [], "texts": [], "cut_box": None}
    for entity in block:
        kind, layer = entity.dxftype(), entity.dxf.layer
        if kind in ("POLYLINE", "LWPOLYLINE"):
            points = polyline_points(entity)
            if layer == "1":
                if entity.is_closed:
                    report["closed_cut_lines"].append(len(points))
                    report["cut_areas"].append(abs(shoelace(points)))
                    xs = [x + at.x for x, _ in points]
                    ys = [y + at.y for _, y in points]
                    report["cut_box"] = [min(xs), min(ys), max(xs), max(ys)]
                else:
                    report["open_cut_lines"] += 1
            elif layer == "8":
                report["internal_lines"].append(len(points) + (1 if entity.is_closed else 0))
            elif layer == "14":
                report["sew_lines"].append(len(points) + (1 if entity.is_closed else 0))
        elif kind == "POINT" and layer == "4":
            report["notch_points"].append([entity.dxf.location.x, entity.dxf.location.y, entity.dxf.angle])
        elif kind == "LINE" and layer == "4":
            report["notch_lines"] += 1
        elif kind == "LINE" and layer == "7":
            report["grain_lines"].append([entity.dxf.start.x, entity.dxf.start.y, entity.dxf.end.x, entity.dxf.end.y])
        elif kind == "TEXT" and layer == "1":
            report["texts"].append(entity.dxf.text)
    return report


def seqend_owner_quirk(fix):
    return fix.code == AuditError.INVALID_OWNER_HANDLE and fix.message.startswith("Deleted SEQEND(")


def main():
    doc = ezdxf.readfile(sys.argv[1])
    auditor = doc.audit()
    result = {
        "dxfversion": doc.dxfversion,
        "insunits": doc.header.get("$INSUNITS", 0),
        "audit_errors": [str(error.message) for error in auditor.errors],
        "audit_fixes": [str(fix.message) for fix in auditor.fixes if not seqend_owner_quirk(fix)],
        "modelspace_texts": [e.dxf.text for e in doc.modelspace().query("TEXT") if e.dxf.layer == "1"],
        "pieces": [],
    }
    for insert in doc.modelspace().query("INSERT"):
        report = block_report(doc.blocks.get(insert.dxf.name), insert.dxf.insert)
        report["block"] = insert.dxf.name
        result["pieces"].append(report)
    with open(sys.argv[2], "w", encoding="utf-8") as out:
        json.dump(result, out)


if __name__ == "__main__":
    main()
