#!/usr/bin/env python3
"""Regenerates tests/corpus/bad/: deliberately broken .bpt and .patchwork files.
tests/test_bad_input.cpp checks that each is refused with an InputError naming the file and the
line (or JSON field) given in its table. Run from this directory: python3 make_bad_corpus.py"""
import json, os

BAD = 'bad'
os.makedirs(BAD, exist_ok=True)

def w(name, text):
    data = text if isinstance(text, bytes) else text.encode()
    with open(os.path.join(BAD, name), 'wb') as f:
        f.write(data)

# ---- .bpt ----
pts = [f"{i % 4} {i // 4} 0.5" for i in range(16)]
def patch(points=None, degree="3 3"):
    return degree + "\n" + "\n".join(points or pts) + "\n"
good1 = "1\n" + patch()
w("truncated.bpt", "2\n" + patch() + "3 3\n" + "\n".join(pts[:7]) + "\n")
w("truncated_mid_line.bpt", "1\n3 3\n" + "\n".join(pts[:4]) + "\n1.0 2.0")
w("count_too_high.bpt", "3\n" + patch() + patch())
w("count_too_low.bpt", "1\n" + patch() + patch())
w("trailing_garbage.bpt", good1 + "\nthe end\n")
w("bad_degree.bpt", "1\n" + patch(degree="2 3"))
w("bad_degree_line.bpt", "1\n" + patch(degree="3"))
w("degree_text.bpt", "1\n" + patch(degree="three three"))
w("nan.bpt", "1\n" + patch(pts[:5] + ["nan 0 0"] + pts[6:]))
w("inf.bpt", "1\n" + patch(pts[:9] + ["0 -inf 0"] + pts[10:]))
w("huge.bpt", "1\n" + patch(pts[:2] + ["1e300 0 0"] + pts[3:]))
w("beyond_limit.bpt", "1\n" + patch(pts[:2] + ["0 0 1000000000.5"] + pts[3:]))
w("overflow.bpt", "1\n" + patch(pts[:15] + ["0 0 1e400"]))
w("letters.bpt", "1\n" + patch(pts[:3] + ["1.0 abc 2.0"] + pts[4:]))
w("number_suffix.bpt", "1\n" + patch(pts[:3] + ["1.0 2.0x 2.0"] + pts[4:]))
w("missing_number.bpt", "1\n" + patch(pts[:10] + ["1.0 2.0"] + pts[11:]))
w("extra_number.bpt", "1\n" + patch(pts[:10] + ["1.0 2.0 3.0 4.0"] + pts[11:]))
w("blank_point_line.bpt", "1\n" + patch(pts[:10] + [""] + pts[11:]))
w("empty.bpt", "")
w("whitespace_only.bpt", "  \n\n \t\n")
w("negative_count.bpt", "-1\n" + patch())
w("count_text.bpt", "thirty-two\n" + patch())
w("count_above_limit.bpt", "1000001\n" + patch())
w("count_huge.bpt", "99999999999999999999999\n" + patch())
w("binary.bpt", b"\x00\x01\x02\xff\xfe\n\x89PNG\r\n")
w("crlf_truncated.bpt", ("1\n" + patch()).replace("\n", "\r\n")[:-30])

# ---- .patchwork ----
def doc(**over):
    d = {"format": "patchwork", "version": 1, "name": "t", "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
         "patches": [{"idx": [0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0]}, {"idx": [0] * 16}]}
    d.update(over)
    return d
def wj(name, d):
    w(name, json.dumps(d, indent=2) + "\n")
good = doc()
txt = json.dumps(good, indent=2)
w("malformed.patchwork", txt.replace('"name": "t",', '"name": "t",,'))
w("malformed_missing_comma.patchwork", '{\n  "format": "patchwork"\n  "version": 1\n}\n')
w("truncated.patchwork", txt[:len(txt) // 2])
w("empty.patchwork", "")
w("not_json.patchwork", "1\n3 3\n0 0 0\n")
w("nan.patchwork", '{"format": "patchwork", "version": 1,\n"points": [[0, 0, 0],\n[1, NaN, 0]],\n"patches": []}\n')
w("overflow.patchwork", '{"format":"patchwork","version":1,\n"points":[[0,0,0],\n[1e400,0,0]],\n"patches":[]}\n')
wj("not_object.patchwork", [1, 2, 3])
wj("wrong_format.patchwork", doc(format="gltf"))
wj("missing_format.patchwork", {k: v for k, v in good.items() if k != "format"})
wj("missing_version.patchwork", {k: v for k, v in good.items() if k != "version"})
wj("version_string.patchwork", doc(version="1"))
wj("version_zero.patchwork", doc(version=0))
wj("newer_version.patchwork", doc(version=2))
wj("missing_points.patchwork", {k: v for k, v in good.items() if k != "points"})
wj("points_not_array.patchwork", doc(points={"0": [0, 0, 0]}))
wj("point_two_coords.patchwork", doc(points=[[0, 0, 0], [1, 0], [0, 1, 0]]))
wj("point_string_coord.patchwork", doc(points=[[0, 0, 0], [1, "0", 0], [0, 1, 0]]))
wj("huge_coordinate.patchwork", doc(points=[[0, 0, 0], [1, 0, 1e300], [0, 1, 0]]))
wj("index_out_of_range.patchwork", doc(patches=[{"idx": [0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 3]}]))
wj("negative_index.patchwork", doc(patches=[{"idx": [0, 1, 2, 0, 1, 2, 0, -1, 2, 0, 1, 2, 0, 1, 2, 0]}]))
wj("fractional_index.patchwork", doc(patches=[{"idx": [0, 1, 2, 0, 1, 2, 0, 1.5, 2, 0, 1, 2, 0, 1, 2, 0]}]))
wj("idx_count.patchwork", doc(patches=[{"idx": [0, 1, 2]}]))
wj("idx_missing.patchwork", doc(patches=[{"name": "no indices"}]))
wj("patch_not_object.patchwork", doc(patches=[[0] * 16]))
wj("patches_wrong_type.patchwork", doc(patches="none"))
wj("unknown_basis.patchwork", doc(patches=[{"idx": [0] * 16, "basis": "nurbs"}]))
wj("tension_string.patchwork", doc(patches=[{"idx": [0] * 16, "tension": "half"}]))
wj("tess_override_level.patchwork", doc(patches=[{"idx": [0] * 16, "tess": [1, 2, 3, 4, 5, 1000]}]))
wj("surface_idx_count.patchwork", doc(surfaces=[{"rows": 4, "cols": 4, "idx": [0] * 15}]))
wj("surface_rows_zero.patchwork", doc(surfaces=[{"rows": 0, "cols": 4, "idx": []}]))
wj("surface_too_big.patchwork", doc(surfaces=[{"rows": 5000, "cols": 4, "idx": []}]))
wj("surface_index_out_of_range.patchwork", doc(surfaces=[{"rows": 1, "cols": 4, "idx": [0, 1, 2, 7]}]))
wj("join_out_of_range.patchwork", doc(joins=[{"a": 0, "edgeA": "u1", "b": 5, "edgeB": "u0", "reversed": False,
                                               "continuity": "C1", "alpha": 1}]))
wj("join_negative_patch.patchwork", doc(joins=[{"a": -1, "edgeA": "u1", "b": 1, "edgeB": "u0"}]))
wj("join_bad_edge.patchwork", doc(joins=[{"a": 0, "edgeA": "w0", "b": 1, "edgeB": "u0"}]))
wj("join_bad_continuity.patchwork", doc(joins=[{"a": 0, "edgeA": "u1", "b": 1, "edgeB": "u0", "continuity": "C2"}]))
wj("join_bad_alpha.patchwork", doc(joins=[{"a": 0, "edgeA": "u1", "b": 1, "edgeB": "u0", "continuity": "G1", "alpha": -2}]))
wj("join_missing_edge.patchwork", doc(joins=[{"a": 0, "b": 1, "edgeB": "u0"}]))
wj("joins_not_array.patchwork", doc(joins={"a": 0}))
wj("tess_wrong_type.patchwork", doc(tess={"linked": "yes"}))
wj("tess_level_too_high.patchwork", doc(tess={"outer": [16, 16, 16, 65]}))
wj("tess_unknown_spacing.patchwork", doc(tess={"spacing": "fractional"}))
wj("display_wrong_type.patchwork", doc(display={"lightDir": [0, 1]}))
wj("camera_wrong_type.patchwork", doc(camera={"distance": "far"}))
wj("camera_zero_distance.patchwork", doc(camera={"distance": 0}))
wj("name_number.patchwork", doc(name=42))
w("deep_nesting.patchwork", '{"format": "patchwork", "version": 1,\n"points": ' + "[" * 1000 + "]" * 1000 + "}\n")

# ---- .patchwork: cubic Bézier triangles ----
tri = list(range(3)) + [0, 1, 2, 0, 1, 2, 0]
wj("triangle_idx_count.patchwork", doc(triangles=[{"idx": [0, 1, 2]}]))
wj("triangle_idx_missing.patchwork", doc(triangles=[{"name": "no indices"}]))
wj("triangle_index_out_of_range.patchwork", doc(triangles=[{"idx": tri[:9] + [3]}]))
wj("triangle_negative_index.patchwork", doc(triangles=[{"idx": tri[:4] + [-1] + tri[5:]}]))
wj("triangle_fractional_index.patchwork", doc(triangles=[{"idx": tri[:2] + [0.5] + tri[3:]}]))
wj("triangle_not_object.patchwork", doc(triangles=[tri]))
wj("triangles_not_array.patchwork", doc(triangles={"idx": tri}))
wj("triangle_tess_count.patchwork", doc(triangles=[{"idx": tri, "tess": [4, 4, 4, 4, 4, 4]}]))
wj("triangle_tess_level.patchwork", doc(triangles=[{"idx": tri, "tess": [4, 4, 4, 1000]}]))
wj("triangle_name_number.patchwork", doc(triangles=[{"idx": tri}, {"idx": tri, "name": 7}]))
w("triangle_nan.patchwork", '{"format": "patchwork", "version": 1,\n"points": [[0, 0, 0]],\n"patches": [],\n'
  '"triangles": [{"idx": [0, 0, 0, 0, 0, 0, 0, 0, 0, 0],\n"tess": [4, NaN, 4, 4]}]}\n')
