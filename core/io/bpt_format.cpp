// The tea-set .bpt format: strict line-by-line parsing with line numbers in every error, and
// round-trip exact writing.
#include "core/io/bpt_format.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/limits.hpp"
#include "core/model/join_detect.hpp"
#include "core/ops/orientation.hpp"

namespace pw {
inline namespace io {

namespace {

// Splits the text into lines (LF or CRLF), remembering 1-based line numbers.
class LineReader {
public:
    explicit LineReader(std::string_view text) : text_(text) {}

    // Next line without its terminator; false at the end of the text.
    bool next(std::string_view& line) {
        if (pos_ >= text_.size()) return false;
        size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) end = text_.size();
        line = text_.substr(pos_, end - pos_);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos_ = end + 1;
        ++lineNo_;
        return true;
    }
    int lineNo() const { return lineNo_; }

private:
    std::string_view text_;
    size_t pos_ = 0;
    int lineNo_ = 0;
};

bool isSeparator(char c) { return c == ' ' || c == '\t' || c == ','; }

// Tokens separated by spaces, tabs or commas (some copies of the tea set use commas).
std::vector<std::string_view> tokens(std::string_view line) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSeparator(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !isSeparator(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

bool isBlank(std::string_view line) {
    for (char c : line)
        if (c != ' ' && c != '\t') return false;
    return true;
}

std::string quoted(std::string_view token) {
    constexpr size_t kMax = 40;
    std::string s(token.substr(0, kMax));
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return "'" + s + (token.size() > kMax ? "...'" : "'");
}

// An unsigned integer occupying the whole token.
bool parseCount(std::string_view token, uint64_t& value) {
    const char* end = token.data() + token.size();
    auto [ptr, ec] = std::from_chars(token.data(), end, value);
    return ec == std::errc() && ptr == end;
}

class BptParser {
public:
    BptParser(std::string_view text, const std::string& source, std::vector<std::string>* notes)
        : reader_(text), source_(source), notes_(notes) {}

    // Line 1: the patch count, checked against the limits.
    uint64_t header() {
        std::string_view line;
        if (!nextContentLine(line)) fail(1, "empty file; expected the number of patches on the first line");
        const auto countTok = tokens(line);
        uint64_t count = 0;
        if (countTok.size() != 1 || !parseCount(countTok[0], count)) {
            const bool digits = countTok.size() == 1 && countTok[0].find_first_not_of("0123456789") == std::string_view::npos;
            if (digits)  // too many digits for 64 bits
                fail(reader_.lineNo(), quoted(countTok[0]) + " patches; the limit is " + std::to_string(limits::kMaxPatches));
            fail(reader_.lineNo(), "expected the number of patches, found " + quoted(line));
        }
        if (count > limits::kMaxPatches)
            fail(reader_.lineNo(), std::to_string(count) + " patches; the limit is " + std::to_string(limits::kMaxPatches));
        // Every patch lists its own 16 points: the count alone says what the file will cost, so a
        // file beyond the point limit is refused here, before the rest is read (issue 44).
        if (count * 16 > limits::kMaxPoints)
            fail(reader_.lineNo(), std::to_string(count) + " patches list " + std::to_string(count * 16) +
                                       " control points; the limit is " + std::to_string(limits::kMaxPoints) + " (" +
                                       std::to_string(limits::kMaxPoints / 16) + " patches in a .bpt)");
        return count;
    }

    Document parse() {
        std::string_view line;
        const uint64_t count = header();

        Document doc;
        doc.name = std::filesystem::path(source_).stem().string();
        // Do not trust the count for the reservation: a short file may claim a million patches.
        doc.patches.reserve(std::min<uint64_t>(count, 4096));
        doc.points.reserve(std::min<uint64_t>(count, 4096) * 16);
        for (uint64_t p = 0; p < count; ++p) {
            const std::string which = "patch " + std::to_string(p + 1) + " of " + std::to_string(count);
            // Degree line "3 3".
            if (!reader_.next(line)) fail(reader_.lineNo() + 1, "file ends early: expected the degree line '3 3' of " + which);
            const auto deg = tokens(line);
            uint64_t du = 0, dv = 0;
            if (deg.size() != 2 || !parseCount(deg[0], du) || !parseCount(deg[1], dv))
                fail(reader_.lineNo(), "expected the degree line '3 3' of " + which + ", found " + quoted(line));
            if (du != 3 || dv != 3)
                fail(reader_.lineNo(), "degree " + std::to_string(du) + " " + std::to_string(dv) + " of " + which +
                                           " is not supported; only bicubic patches ('3 3') are");
            Patch patch;
            for (int k = 0; k < 16; ++k) {
                if (!reader_.next(line))
                    fail(reader_.lineNo() + 1, "file ends early: expected control point " + std::to_string(k + 1) + " of 16 of " + which);
                patch.idx[k] = static_cast<uint32_t>(doc.points.size());
                doc.points.push_back(parsePoint(line));
            }
            doc.patches.push_back(std::move(patch));
        }
        // Only blank lines may follow.
        while (reader_.next(line))
            if (!isBlank(line))
                fail(reader_.lineNo(), "unexpected content after the last of " + std::to_string(count) + " patches: " + quoted(line));

        mergeCoincidentPoints(doc);
        if (doc.points.size() > limits::kMaxPoints)
            fail(0, std::to_string(doc.points.size()) + " distinct points; the limit is " + std::to_string(limits::kMaxPoints));
        size_t nonManifold = 0;
        doc.joins = detectJoins(doc, {}, &nonManifold);
        // The format has no orientation convention: the teacup comes inside out. After a flip the
        // pool is renumbered by first use and the joins detected afresh, so that writing and
        // reading the file back gives the same document.
        if (orientOutward(doc)) {
            renumberPoolByFirstUse(doc);
            doc.joins = detectJoins(doc, {}, &nonManifold);
        }
        if (nonManifold > 0 && notes_)
            notes_->push_back(std::to_string(nonManifold) + (nonManifold == 1 ? " edge is" : " edges are") +
                              " shared by more than two patches (stacked copies or a fin) and left unjoined");
        frameCamera(doc);
        return doc;
    }

private:
    [[noreturn]] void fail(int line, const std::string& why) const { throw InputError(source_, why, line); }

    bool nextContentLine(std::string_view& line) {
        while (reader_.next(line))
            if (!isBlank(line)) return true;
        return false;
    }

    Vec3 parsePoint(std::string_view line) {
        const auto tok = tokens(line);
        if (tok.size() != 3)
            fail(reader_.lineNo(),
                 "expected 3 numbers (x y z), found " + std::to_string(tok.size()) + (tok.empty() ? "" : ": " + quoted(line)));
        Vec3 p;
        for (int c = 0; c < 3; ++c) p[c] = parseNumber(tok[c], "xyz"[c]);
        return p;
    }

    double parseNumber(std::string_view token, char axis) {
        std::string_view t = token;
        if (!t.empty() && t.front() == '+') t.remove_prefix(1);  // from_chars refuses a leading '+'
        double v = 0;
        const char* end = t.data() + t.size();
        auto [ptr, ec] = std::from_chars(t.data(), end, v, std::chars_format::general);
        const std::string what = std::string(1, axis) + " coordinate " + quoted(token);
        if (ec == std::errc::result_out_of_range)
            fail(reader_.lineNo(), what + " is beyond the range of a double (coordinates are limited to ±1e9)");
        if (ec != std::errc() || ptr != end || t.empty()) fail(reader_.lineNo(), what + " is not a number");
        if (!std::isfinite(v)) fail(reader_.lineNo(), what + " is not finite");
        if (std::abs(v) > limits::kMaxCoordinate) fail(reader_.lineNo(), what + " is too large (the limit is ±1e9)");
        return v;
    }

    static void renumberPoolByFirstUse(Document& doc) {
        std::vector<uint32_t> newIndex(doc.points.size(), UINT32_MAX);
        std::vector<Vec3> points;
        points.reserve(doc.points.size());
        for (Patch& p : doc.patches)
            for (uint32_t& i : p.idx) {
                if (newIndex[i] == UINT32_MAX) {
                    newIndex[i] = static_cast<uint32_t>(points.size());
                    points.push_back(doc.points[i]);
                }
                i = newIndex[i];
            }
        doc.points = std::move(points);
    }

    static void frameCamera(Document& doc) {
        const Bounds b = computeBounds(doc.points);
        if (b.empty) return;
        const Vec3 c = 0.5 * (b.min + b.max);
        doc.camera.target = {c.x, c.y, c.z};
        doc.camera.distance = std::max(2.2 * b.diagonal(), 1e-3);
        // .bpt carries no up axis. Objects stand on their flattest side, so take the axis of the
        // smallest extent as up when that is y (the teacup); z otherwise (teapot; the teaspoon lies flat).
        const Vec3 ext = b.max - b.min;
        doc.camera.zUp = !(ext.y < ext.x && ext.y < ext.z);
    }

    LineReader reader_;
    std::string source_;
    std::vector<std::string>* notes_;
};

void appendNumber(std::string& out, double v) {
    char buf[64];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
    out.append(buf, ec == std::errc() ? ptr : buf);
}

}  // namespace

Document parseBpt(std::string_view text, const std::string& sourceName, std::vector<std::string>* notes) {
    return BptParser(text, sourceName, notes).parse();
}

Document loadBpt(const std::filesystem::path& path, std::vector<std::string>* notes) {
    // The header first, from the file's first lines: a count beyond the limits is refused before
    // the whole file (up to limits::kMaxFileBytes) is read.
    // readFileHead refuses a FIFO, device or /proc file before reading anything (a FIFO hung here).
    std::string head = readFileHead(path, 4096);
    if (const size_t lastLine = head.rfind('\n'); lastLine != std::string::npos) {
        head.resize(lastLine + 1);
        if (head.find_first_not_of(" \t\r\n") != std::string::npos) (void)BptParser(head, path.string(), nullptr).header();
    }
    return parseBpt(readFileLimited(path), path.string(), notes);
}

std::string formatBpt(const Document& doc) {
    if (!doc.triangles.empty())
        throw InputError(doc.name.empty() ? "document" : doc.name,
                         "Bézier triangles cannot be written as .bpt, which holds rectangular patches only", 0, "triangles[0]");
    if (!doc.curves.empty())
        throw InputError(doc.name.empty() ? "document" : doc.name,
                         "Bézier curves cannot be written as .bpt, which holds rectangular patches only", 0, "curves[0]");
    const std::vector<PatchInstance> windows = expandPatches(doc);
    std::string out;
    out.reserve(windows.size() * 16 * 32 + 16);
    out += std::to_string(windows.size());
    out += '\n';
    for (const PatchInstance& w : windows) {
        if (w.basis != Basis::Bezier) {
            const std::string field =
                w.patch >= 0 ? "patches[" + std::to_string(w.patch) + "]" : "surfaces[" + std::to_string(w.surface) + "]";
            throw InputError(doc.name.empty() ? "document" : doc.name,
                             "basis " + std::string(basisName(w.basis)) + " cannot be written as .bpt, which holds Bézier patches only", 0,
                             field);
        }
        out += "3 3\n";
        for (int k = 0; k < 16; ++k) {
            const Vec3& p = doc.points.at(w.idx[k]);
            appendNumber(out, p.x);
            out += ' ';
            appendNumber(out, p.y);
            out += ' ';
            appendNumber(out, p.z);
            out += '\n';
        }
    }
    return out;
}

}  // namespace io
}  // namespace pw
