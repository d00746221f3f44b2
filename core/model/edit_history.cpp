#include "core/model/edit_history.hpp"

#include <stdexcept>

namespace pw {
inline namespace model {

namespace {

// True when the two documents differ only in point coordinates (same pool size).
bool onlyPointsDiffer(const Document& a, const Document& b) {
    return a.points.size() == b.points.size() && a.patches == b.patches && a.surfaces == b.surfaces && a.triangles == b.triangles &&
           a.curves == b.curves && a.joins == b.joins && a.tess == b.tess && a.display == b.display && a.camera == b.camera &&
           a.displacement == b.displacement && a.tolerances == b.tolerances && a.weights == b.weights && a.name == b.name &&
           a.constructions == b.constructions && a.unit == b.unit;
}

const std::string kEmpty;

}  // namespace

EditHistory::EditHistory(size_t maxSteps) : maxSteps_(maxSteps == 0 ? 1 : maxSteps) {}

void EditHistory::commit(const Document& before, const Document& after, std::string label) {
    Step step;
    step.label = std::move(label);
    if (onlyPointsDiffer(before, after)) {
        for (size_t i = 0; i < before.points.size(); ++i)
            if (before.points[i] != after.points[i]) step.points.push_back({static_cast<uint32_t>(i), before.points[i], after.points[i]});
        if (step.points.empty()) return;
    } else {
        step.before = std::make_unique<Document>(before);
        step.after = std::make_unique<Document>(after);
    }
    steps_.resize(cursor_);                                               // a new edit drops the redo branch
    if (savedCursor_ > static_cast<int64_t>(cursor_)) savedCursor_ = -1;  // saved state is gone
    steps_.push_back(std::move(step));
    ++cursor_;
    if (steps_.size() > maxSteps_) {
        steps_.erase(steps_.begin());
        --cursor_;
        --savedCursor_;
    }
}

const std::string& EditHistory::undoLabel() const { return canUndo() ? steps_[cursor_ - 1].label : kEmpty; }
const std::string& EditHistory::redoLabel() const { return canRedo() ? steps_[cursor_].label : kEmpty; }

void EditHistory::undo(Document& doc) {
    if (canUndo()) restore(steps_[--cursor_], doc, false);
}

void EditHistory::redo(Document& doc) {
    if (canRedo()) restore(steps_[cursor_++], doc, true);
}

void EditHistory::restore(const Step& s, Document& doc, bool forward) {
    if (const std::unique_ptr<Document>& whole = forward ? s.after : s.before) {
        doc = *whole;
        return;
    }
    for (const PointChange& c : s.points) {
        if (c.index >= doc.points.size()) throw std::logic_error("EditHistory: document does not match history");
        doc.points[c.index] = forward ? c.after : c.before;
    }
}

void EditHistory::clear() {
    steps_.clear();
    cursor_ = 0;
    savedCursor_ = 0;
}

}  // namespace model
}  // namespace pw
