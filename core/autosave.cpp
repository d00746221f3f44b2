#include "core/autosave.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>
#include <unistd.h>

#include "core/document_io.hpp"
#include "core/file_io.hpp"
#include "core/json_guard.hpp"

namespace pw {

namespace fs = std::filesystem;

fs::path autosaveDirectory() {
    if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return fs::path(x) / "patchwork";
    if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".local" / "state" / "patchwork";
    return fs::temp_directory_path() / "patchwork-state";
}

Autosaver::Autosaver(fs::path dir, int pid) : dir_(std::move(dir)), pid_(pid ? pid : int(::getpid())) {
    doc_ = dir_ / ("autosave-" + std::to_string(pid_) + ".patchwork");
    note_ = dir_ / ("autosave-" + std::to_string(pid_) + ".json");
}

void Autosaver::save(const Document& doc, const std::string& originalPath) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    saveDocument(doc, doc_);
    const long long now =
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
    nlohmann::json j{{"original", originalPath}, {"pid", pid_}, {"savedAt", now}, {"name", doc.name}};
    writeFileAtomic(note_, j.dump(2));
}

void Autosaver::discard() {
    std::error_code ec;
    fs::remove(doc_, ec);
    fs::remove(note_, ec);
}

std::vector<AutosaveEntry> findRecoverableAutosaves(const fs::path& dir) {
    std::vector<AutosaveEntry> out;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return out;
    for (const fs::directory_entry& de : fs::directory_iterator(dir, ec)) {
        const fs::path p = de.path();
        if (p.extension() != ".json" || p.filename().string().rfind("autosave-", 0) != 0) continue;
        AutosaveEntry e;
        e.note = p;
        e.document = fs::path(p).replace_extension(".patchwork");
        if (!fs::exists(e.document, ec)) continue;
        try {
            const nlohmann::json j = parseJsonGuarded(readFileLimited(p), p.string());
            e.originalPath = j.value("original", std::string());
            e.pid = j.value("pid", 0);
            e.savedAtUnix = j.value("savedAt", 0LL);
        } catch (...) {
            continue;
        }
        // Still running (another editor window)? Then it is not a crash.
        if (e.pid > 0 && e.pid != int(::getpid()) && (::kill(e.pid, 0) == 0 || errno == EPERM)) continue;
        out.push_back(e);
    }
    std::sort(out.begin(), out.end(), [](const AutosaveEntry& a, const AutosaveEntry& b) { return a.savedAtUnix > b.savedAtUnix; });
    return out;
}

void removeAutosave(const AutosaveEntry& e) {
    std::error_code ec;
    fs::remove(e.document, ec);
    fs::remove(e.note, ec);
}

}  // namespace pw
