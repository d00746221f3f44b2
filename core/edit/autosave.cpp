#include "core/edit/autosave.hpp"

#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/json_guard.hpp"
#include "core/io/document_io.hpp"

namespace pw {
inline namespace edit {

namespace fs = std::filesystem;

fs::path autosaveDirectory() {
    if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return fs::path(x) / "patchwork";
    if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".local" / "state" / "patchwork";
    // No HOME: a folder of this user's own in the shared temp folder (ensurePrivateDirectory refuses
    // one that another user made first).
    return fs::temp_directory_path() / ("patchwork-state-" + std::to_string(::geteuid()));
}

void ensurePrivateDirectory(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    struct stat st {};
    if (::lstat(dir.c_str(), &st) != 0) throw OutputError(dir.string(), std::string("cannot create the folder: ") + std::strerror(errno));
    if (!S_ISDIR(st.st_mode)) throw OutputError(dir.string(), "is not a folder (a symbolic link or a file is in the way)");
    if (st.st_uid != ::geteuid()) throw OutputError(dir.string(), "belongs to another user; autosaves stay in a folder of your own");
    if ((st.st_mode & 077) != 0 && ::chmod(dir.c_str(), 0700) != 0)
        throw OutputError(dir.string(), std::string("others can read it and it cannot be made private: ") + std::strerror(errno));
}

bool isPrivateDirectory(const fs::path& dir) {
    struct stat st {};
    return ::lstat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == ::geteuid() && (st.st_mode & 077) == 0;
}

std::string autosaveNote(const std::string& originalPath, int pid, const std::string& name, bool emergency) {
    const long long now = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
    nlohmann::json j{{"original", originalPath}, {"pid", pid}, {"savedAt", now}, {"name", name}};
    if (emergency) j["emergency"] = true;
    return j.dump(2);
}

Autosaver::Autosaver(fs::path dir, int pid) : dir_(std::move(dir)), pid_(pid ? pid : int(::getpid())) {
    doc_ = dir_ / ("autosave-" + std::to_string(pid_) + ".patchwork");
    note_ = dir_ / ("autosave-" + std::to_string(pid_) + ".json");
}

void Autosaver::save(const Document& doc, const std::string& originalPath) {
    ensurePrivateDirectory(dir_);
    saveDocument(doc, doc_);
    writeFileAtomic(note_, autosaveNote(originalPath, pid_, doc.name));
    // This autosave holds the adopted (recovered) work now.
    if (adopted_) removeAutosave(*adopted_);
    adopted_.reset();
}

void Autosaver::adopt(const AutosaveEntry& recovered) { adopted_ = recovered; }

void Autosaver::discard() {
    if (adopted_) removeAutosave(*adopted_);
    adopted_.reset();
    std::error_code ec;
    fs::remove(doc_, ec);
    fs::remove(note_, ec);
}

std::vector<AutosaveEntry> findRecoverableAutosaves(const fs::path& dir) {
    std::vector<AutosaveEntry> out;
    std::error_code ec;
    if (!isPrivateDirectory(dir)) return out;  // never offer files another user could have planted
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

}  // namespace edit
}  // namespace pw
