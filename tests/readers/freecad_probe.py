# Run by tests/test_foreign_readers.cpp through `freecadcmd` (FreeCAD 0.20, Debian's): reads every
# STEP file in $PW_PROBE_DIR (valid, solids, shells, free edges) as a FreeCAD user's File > Import does (Import.insert; merge and link
# groups off, since freecadcmd 0.20 crashes on assemblies with them on) and as Part.read, makes a
# filleted box, a plate with a hole, a loft and a sweep as a FreeCAD user would and writes them to
# $PW_PROBE_DIR/NAME.step, reads every
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


def part(name, shape):
    """A part as a FreeCAD user makes it, written to NAME.step, with its faces and area."""
    shape.exportStep(os.path.join(folder, name + ".step"))
    out[name] = {"faces": len(shape.Faces), "area": shape.Area}


box = Part.makeBox(40, 30, 20)
part("fillet_box", box.makeFillet(4, box.Edges))
# A plate with a hole (a face with an inner wire), a lofted vase (degree 14 x 2 faces) and a
# swept pipe (degree 6 x 11, rational), the latter two closed with their planar caps.
part("holed_plate", Part.makeBox(40, 30, 3).cut(Part.makeCylinder(6, 3, FreeCAD.Vector(15, 12, 0))))
rings = [Part.Wire(Part.makeCircle(r, FreeCAD.Vector(0, 0, z))) for r, z in ((10, 0), (6, 20), (12, 40))]
part("loft", Part.makeLoft(rings, True, False))
spine = Part.BSplineCurve()
spine.interpolate([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(10, 0, 10), FreeCAD.Vector(20, 5, 20), FreeCAD.Vector(30, 0, 25)])
ring = Part.Wire(Part.makeCircle(2, FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 0, 1)))
part("sweep", Part.Wire(spine.toShape()).makePipeShell([ring], True, True))

with open(os.path.join(folder, "freecad.json"), "w") as f:
    json.dump(out, f)
