#include "core/edit/edit_session.hpp"

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/edit/edit_invariants.hpp"
#include "core/edit/live_constructions.hpp"
#include "core/io/document_io.hpp"
#include "core/model/placement.hpp"
#include "core/ops/patch_ops.hpp"

namespace pw {
inline namespace edit {

EditSession::EditSession() {
    doc.name = "untitled";
    markCommitted();
}

const std::string& EditSession::title() const {
    static const std::string kUntitled = "untitled";
    if (!path_.empty()) return path_;
    return doc.name.empty() ? kUntitled : doc.name;
}

void EditSession::changed(bool topology) {
    ++version_;
    ++shapeVersion_;
    if (topology) ++topologyVersion_;
    clampSelection(sel, doc);
}

void EditSession::markCommitted() {
    committed_ = doc;
    ++generation_;
}

void EditSession::reset(Document d, const std::string& path) {
    doc = std::move(d);
    try {  // errors of constructions whose inputs no longer fit (a file edited elsewhere)
        notes_ = refreshConstructions(doc);
    } catch (const EditError& e) {
        notes_ = {e.what()};
    }
    markCommitted();
    history_.clear();
    history_.markSaved();
    forceModified_ = false;
    path_ = path;
    diskStamp_ = path.empty() ? FileStamp{} : fileStamp(path);
    sel.clear();
    camera = doc.camera;
    ++serial_;
    changed(true);
}

void EditSession::newDocument() {
    Document d;
    d.name = "untitled";
    addFlatPatch(d, Vec3(0.0), 2.0, true);
    reset(std::move(d), "");
}

std::vector<std::string> EditSession::open(const std::string& path, bool partial) {
    LoadReport report;                        // a Patchwork glTF saves back with its own export options
    const FileStamp stamp = fileStamp(path);  // before the read: a write during it shows at the next save
    reset(loadDocument(path, &report, partial), path);
    diskStamp_ = stamp;
    if (report.exportOptions) exportOptions = *report.exportOptions;
    return std::move(report.notes);
}

MergedRange EditSession::import(const std::string& path) {
    const Document from = loadDocument(path, nullptr, true);  // the editor shows what a CAD file left out when it opens
    MergedRange r;
    // Beside what is there, never inside it (the file's own coordinates where they are clear).
    apply(
        "Import " + std::filesystem::path(path).filename().string(),
        [&](Document& d) {
            r = mergeDocument(d, from);
            moveClearOfExisting(d, r.firstPoint);
        },
        true, Brought::File);
    // The imported content arrives selected: its points, and the patch when it is the only thing.
    sel.clear();
    for (uint32_t i = 0; i < r.pointCount; ++i) sel.points.push_back(r.firstPoint + i);
    if (r.patchCount == 1 && r.surfaceCount + r.triangleCount + r.curveCount == 0) sel.patch = int(r.firstPatch);
    return r;
}

void EditSession::commit(const std::string& label) {
    history_.commit(committed_, doc, label);
    markCommitted();
    ++version_;
    ++shapeVersion_;
}

bool EditSession::undo() { return step(false); }
bool EditSession::redo() { return step(true); }

bool EditSession::step(bool forward) {
    if (!(forward ? history_.canRedo() : history_.canUndo())) return false;
    if (forward)
        history_.redo(doc);
    else
        history_.undo(doc);
    markCommitted();
    changed(true);
    return true;
}

void EditSession::apply(const std::string& label, const std::function<void(Document&)>& op, bool topology, Brought brought) {
    Document d = doc;
    op(d);
    std::vector<std::string> notes = refreshConstructions(d);
    try {
        checkEditInvariants(doc, d, brought);
    } catch (const EditError& e) {
        // A live surface whose inputs no longer fit keeps its last shape; when that is what broke
        // an invariant (a loft's section moved onto the other: its boundary follows, its inside
        // cannot), the refusal says why.
        std::string why = e.what();
        for (size_t i = 0; i < d.constructions.size(); ++i)
            if (!d.constructions[i].error.empty() && (i >= doc.constructions.size() || doc.constructions[i].error.empty()))
                why += "; the " + std::string(constructionKindName(d.constructions[i].kind)) +
                       " could not follow its inputs: " + d.constructions[i].error;
        throw EditError(why);
    }
    notes_.insert(notes_.end(), notes.begin(), notes.end());
    doc = std::move(d);
    commit(label);
    changed(topology);
}

void EditSession::applyKeepingShape(const std::string& label, const std::function<void(Document&)>& op, bool levels) {
    Document d = doc;
    op(d);
    doc = std::move(d);
    const uint64_t shape = shapeVersion_;
    commit(label);
    shapeVersion_ = shape;
    levels ? changedLevels() : changedSettings();
}

Document EditSession::documentToSave() const {
    Document out = doc;
    out.camera = camera;
    return out;
}

bool EditSession::fileChangedOnDisk() const {
    if (path_.empty() || !diskStamp_.exists) return false;
    const FileStamp now = fileStamp(path_);
    return now.exists && now != diskStamp_;
}

void EditSession::savedTo(const std::string& path) {
    if (!saveKeepsEverything(path)) return;
    path_ = path;
    diskStamp_ = fileStamp(path);
    history_.markSaved();
    forceModified_ = false;
}

std::vector<uint32_t> EditSession::selectedPoints() const {
    std::vector<uint32_t> out = sel.points;
    auto add = [&](const auto& idx) { out.insert(out.end(), idx.begin(), idx.end()); };
    if (sel.patch >= 0 && size_t(sel.patch) < doc.patches.size()) add(doc.patches[size_t(sel.patch)].idx);
    if (sel.surface >= 0 && size_t(sel.surface) < doc.surfaces.size()) add(doc.surfaces[size_t(sel.surface)].idx);
    if (sel.triangle >= 0 && size_t(sel.triangle) < doc.triangles.size()) add(doc.triangles[size_t(sel.triangle)].idx);
    if (sel.curve >= 0 && size_t(sel.curve) < doc.curves.size()) add(doc.curves[size_t(sel.curve)].idx);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Vec3 EditSession::transformPivot() const { return pw::transformPivot(doc, sel, selectedPoints(), pivot, cursor); }

}  // namespace edit
}  // namespace pw
