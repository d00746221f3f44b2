# Run by tests/test_foreign_readers.cpp through `freecadcmd` (FreeCAD 0.20, Debian's): reads every
# STEP file in $PW_PROBE_DIR (valid, solids, shells, free edges) as a FreeCAD user's File > Import does (Import.insert; merge and link
# groups off, since freecadcmd 0.20 crashes on assemblies with them on) and as Part.read, makes a
# filleted box as a FreeCAD user would and writes it to $PW_PROBE_DIR/fillet_box.step, reads every
# IGES file there with Part.read (faces, bounds in millimetres), and writes what it saw to
# $PW_PROBE_DIR/freecad.json.
import json
import os

import FreeCAD
import Import
import Part


def free_edges(shape):
    """Edges on one face only; a face's seam (on it twice) and a pole (no length) are not counted."""
    uses = {}
    for face in shape.Faces:
        for edge in face.Edges:
            if not edge.isSeam(face) and edge.Length > 1e-9:
                uses[edge.hashCode()] = uses.get(edge.hashCode(), 0) + 1
    return sum(1 for n in uses.values() if n == 1)


folder = os.environ["PW_PROBE_DIR"]
out = {}
for name in sorted(os.listdir(folder)):
    if name.endswith(".igs"):  # IGES: Part.read, in FreeCAD's millimetres
        shape = Part.read(os.path.join(folder, name))
        bb = shape.BoundBox
        out[name] = {"faces": len(shape.Faces), "bounds": [bb.XMin, bb.YMin, bb.ZMin, bb.XMax, bb.YMax, bb.ZMax]}
        continue
    if not name.endswith(".step"):
        continue
    path = os.path.join(folder, name)
    shape = Part.read(path)
    bb = shape.BoundBox
    doc = FreeCAD.newDocument(name.replace(".", "_"))
    Import.insert(path, doc.Name, merge=False, useLinkGroup=False)
    objects = [{"type": o.TypeId, "label": o.Label, "solids": len(o.Shape.Solids), "faces": len(o.Shape.Faces)}
               for o in doc.Objects if o.TypeId in ("Part::Feature", "App::Part")]
    out[name] = {
        "valid": shape.isValid(),
        "solids": len(shape.Solids),
        "closed_solids": sum(1 for s in shape.Solids if s.isValid() and s.Volume > 0),
        "faces": len(shape.Faces),
        "shells": len(shape.Shells),
        "free_edges": free_edges(shape),
        "bounds": [bb.XMin, bb.YMin, bb.ZMin, bb.XMax, bb.YMax, bb.ZMax],
        "objects": objects,
    }
    FreeCAD.closeDocument(doc.Name)

box = Part.makeBox(40, 30, 20)
box = box.makeFillet(4, box.Edges)
box.exportStep(os.path.join(folder, "fillet_box.step"))
out["fillet_box"] = {"faces": len(box.Faces), "area": box.Area}

with open(os.path.join(folder, "freecad.json"), "w") as f:
    json.dump(out, f)
