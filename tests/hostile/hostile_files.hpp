// The hostile-input suite's files (issue 44): generated from good seeds for every reader — .bpt,
// .patchwork, .gltf/.glb, STEP and IGES — as structural breakage with the field each must name,
// hand-made hostile values (non-finite, huge, 10 000-digit numbers, oversized entities and counts)
// and deterministic seeded mutations (truncation, bit flips, deletions, duplications, tokens of the
// fuzz dictionaries spliced in). test_hostile_corpus runs the loaders over them in-process; the
// `hostile_suite` program (scripts/hostile.sh) runs the command line over them with per-file limits.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pw::hostile {

struct HostileFile {
    std::filesystem::path file;
    std::string expectField;  // structural glTF cases: the field the refusal must name
    bool mustRefuse = false;  // built to be invalid: exit 0 on it is a silent success
    bool cad = false;         // STEP or IGES (OpenCASCADE in a child process: slower)
    bool large = false;       // tens of megabytes (the full suite only)
};

struct GenerateOptions {
    std::filesystem::path repository;  // the source tree: data/, tests/corpus/good/, fuzz/*.dict
    int mutationsPerSeed = 80;
    bool cad = true;     // STEP and IGES files
    bool large = false;  // large inputs (a million-patch .bpt, a 100 000-patch grid)
};

// Writes the files into `dir` (which must exist) and lists them.
std::vector<HostileFile> generateHostileFiles(const std::filesystem::path& dir, const GenerateOptions& options);

}  // namespace pw::hostile
