// Undo and redo for every edit of a Document. The caller keeps the document; for each finished
// edit (one whole drag counts as one) it hands the state before and after. Edits that only move
// points are stored as sparse diffs; others keep both whole documents.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace model {

class EditHistory {
public:
    explicit EditHistory(size_t maxSteps = 10000);

    // Records the edit before → after under `label` (shown as "Undo <label>"). Drops every redo
    // step. Does nothing when before == after.
    void commit(const Document& before, const Document& after, std::string label);

    bool canUndo() const { return cursor_ > 0; }
    bool canRedo() const { return cursor_ < steps_.size(); }
    const std::string& undoLabel() const;  // empty when nothing to undo
    const std::string& redoLabel() const;

    // Apply to `doc`, which must be the state the history last produced.
    void undo(Document& doc);
    void redo(Document& doc);

    // Unsaved-changes tracking: markSaved() at save; isModified() tells whether the document now
    // differs in history position from the saved one.
    void markSaved() { savedCursor_ = static_cast<int64_t>(cursor_); }
    bool isModified() const { return savedCursor_ != static_cast<int64_t>(cursor_); }

    void clear();
    size_t size() const { return steps_.size(); }

private:
    struct PointChange {
        uint32_t index;
        Vec3 before, after;
    };
    struct Step {
        std::string label;
        std::vector<PointChange> points;          // used when the edit moved points only
        std::unique_ptr<Document> before, after;  // used otherwise
    };

    // Puts doc in the state after (forward) or before step s.
    static void restore(const Step& s, Document& doc, bool forward);

    std::vector<Step> steps_;
    size_t cursor_ = 0;  // steps_[0, cursor_) are done
    int64_t savedCursor_ = 0;
    size_t maxSteps_;
};

}  // namespace model
}  // namespace pw
