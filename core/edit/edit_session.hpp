// The editing session, without a window: the document being edited, its committed state and undo
// history, the selection, the camera, the 3D cursor and the file it belongs to. The editor window
// and `patchwork edit` both drive one of these (through the command table, core/commands/command_table.hpp);
// tests drive it directly.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/base/file_io.hpp"
#include "core/edit/edit_invariants.hpp"
#include "core/io/gltf_export.hpp"
#include "core/model/document.hpp"
#include "core/model/document_merge.hpp"
#include "core/model/edit_history.hpp"
#include "core/select/selection.hpp"
#include "core/select/snapping.hpp"
#include "core/select/soft_selection.hpp"
#include "core/select/symmetry.hpp"

namespace pw {
inline namespace edit {

class EditSession {
public:
    EditSession();

    // The live document. Continuous edits (a drag, an inspector field) write here and call
    // changed(); commit() then records one undo step from committed() to it.
    Document doc;
    Selection sel;
    Camera camera;
    Vec3 cursor{0.0};                     // the 3D cursor: where new geometry is placed
    PivotMode pivot = PivotMode::Median;  // what rotate and scale turn about
    SnapTarget snap = SnapTarget::Grid;   // what moves snap to while Ctrl is held
    Symmetry symmetry;                    // live symmetry: transforms mirror each point's partner
    SoftSelection soft;                   // soft selection: transforms carry the points around partly
    Edge activeEdge = Edge::U1;           // the selected patch's edge nearest the last surface click (extrude, unjoin)
    ExportOptions exportOptions;

    const std::string& path() const { return path_; }  // "" = untitled
    const std::string& title() const;                  // the path, else the document's name, else "untitled"
    const Document& committed() const { return committed_; }
    // Bumped whenever committed() changes (commit, undo, redo, a new document): caches built from
    // the committed state (a factorised solver) compare it.
    uint64_t generation() const { return generation_; }
    // Bumped on every change of `doc` reported to the session; `topologyVersion` only when patches,
    // nets, triangles, curves or joins may have changed (not when points merely moved).
    uint64_t version() const { return version_; }
    uint64_t topologyVersion() const { return topologyVersion_; }
    uint64_t documentSerial() const { return serial_; }  // bumped by reset(): a different document
    // Bumped with version() except when only items' own tessellation levels changed
    // (changedLevels): a renderer rewrites their levels in place instead of uploading the scene.
    uint64_t shapeVersion() const { return shapeVersion_; }
    // Bumped by changedSettings: a preview of document settings that travel in a renderer's
    // options (levels, shading, …), so that nothing needs uploading while a slider moves.
    uint64_t settingsVersion() const { return settingsVersion_; }
    void changed(bool topology);
    void changedLevels() { ++version_; }
    void changedSettings() {
        ++version_;
        ++settingsVersion_;
    }

    // Replaces the document (new, open, recover): history cleared, saved state, camera from the
    // document, selection cleared.
    void reset(Document d, const std::string& path);
    void newDocument();  // untitled, one flat patch (File > New)
    // Returns what the load skipped and why (STEP/IGES faces); a file that came in incomplete is
    // refused unless `partial` (the editor opens it and shows what was left out).
    std::vector<std::string> open(const std::string& path, bool partial = true);
    // Adds a file's content (every kind, with its joins) as one undo step and selects it.
    MergedRange import(const std::string& path);

    // One undo step from committed() to doc under `label` (nothing when they are equal).
    void commit(const std::string& label);
    bool undo();
    bool redo();
    // Runs `op` on a copy of the document; when it returns, the live constructions are made again
    // from their inputs with the joins held (core/edit/live_constructions.hpp), the copy becomes the
    // document and one undo step. When either throws, the document is unchanged and the exception
    // goes on.
    // `brought`: what the edit brings in besides its own work (checkEditInvariants): joins found by
    // detection (mirror), or a file's surfaces and joins (import).
    void apply(const std::string& label, const std::function<void(Document&)>& op, bool topology = true,
               Brought brought = Brought::Nothing);
    // The same for an edit of items' own tessellation levels only (changedLevels).
    void applyLevels(const std::string& label, const std::function<void(Document&)>& op) { applyKeepingShape(label, op, true); }
    // The same for an edit of what a renderer's scene does not hold: settings that travel in its
    // options, names (changedSettings: nothing to upload).
    void applyOutsideScene(const std::string& label, const std::function<void(Document&)>& op) { applyKeepingShape(label, op, false); }

    // The document as it is saved: doc with the session's camera.
    Document documentToSave() const;
    // After a successful write to `path`: a lossless format (saveKeepsEverything) becomes the
    // document's file and the saved state; other formats are exports and change neither.
    void savedTo(const std::string& path);

    // Notes of the last edits for the status line (constructions whose inputs no longer fit, or
    // that were baked); takeNotes() empties them.
    std::vector<std::string> takeNotes() { return std::exchange(notes_, {}); }

    bool isModified() const { return history_.isModified() || forceModified_; }
    // The document's file was written by another program since it was opened or saved here (its
    // stamp differs; a file since deleted does not count): a save would discard that work.
    bool fileChangedOnDisk() const;
    void setForceModified(bool on) { forceModified_ = on; }  // e.g. a recovered autosave
    const EditHistory& history() const { return history_; }

    // The points a transform of the selection moves: the selected points, and every point of the
    // selected patch, net, triangle or curve. Sorted, unique.
    std::vector<uint32_t> selectedPoints() const;
    // The pivot of a transform of selectedPoints() under `pivot`.
    Vec3 transformPivot() const;

private:
    Document committed_;
    EditHistory history_;
    std::string path_;
    FileStamp diskStamp_;  // of path_ when it was opened or saved here
    uint64_t generation_ = 0, version_ = 0, topologyVersion_ = 0, shapeVersion_ = 0, settingsVersion_ = 0, serial_ = 0;
    bool forceModified_ = false;
    std::vector<std::string> notes_;
    void markCommitted();
    // apply() for an edit that leaves what the scene holds: the shape version stays.
    void applyKeepingShape(const std::string& label, const std::function<void(Document&)>& op, bool levels);
    bool step(bool forward);  // undo (false) or redo (true)
};

}  // namespace edit
}  // namespace pw
