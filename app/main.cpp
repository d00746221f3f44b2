// patchwork: entry point. Parses the command line and runs one command; every error about input
// or output is reported as one line naming the file and exits 2.
#include <cstdio>
#include <exception>
#include <iostream>

#include "app/commands.hpp"
#include "core/base/errors.hpp"
#include "core/io/formats.hpp"

int main(int argc, char** argv) {
    CLI::App app{"Patchwork — a Bézier/spline patch editor on the GPU tessellation pipeline"};
    app.require_subcommand(0, 1);
    app.set_version_flag("--version", "patchwork " PATCHWORK_VERSION);
    std::string file;
    app.add_option("file", file, "Document to open (" + pw::formatList(pw::FormatUse::Load, ", ") + "); default: the built-in teapot");

    pw::app::Action run;
    pw::app::registerInfoCommand(app, run);
    pw::app::registerExportCommand(app, run);
    pw::app::registerConvertCommand(app, run);
    pw::app::registerRenderCommand(app, run);
    pw::app::registerBenchCommand(app, run);
    pw::app::registerPresetsCommand(app, run);
    pw::app::registerRoundingCommand(app, run);
    pw::app::registerSweepCommand(app, run);
    pw::app::registerShadersCommand(app, run);
    pw::app::registerEditCommand(app, run);
    pw::app::registerCaptureCommand(app, run);

    pw::app::requirePlainDecimals(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int rc = app.exit(e);
        return rc == 0 ? 0 : 2;
    }
    try {
        if (run) return run();
        return pw::app::runDefault(file);
    } catch (const pw::InputError& e) {
        std::cerr << "patchwork: " << e.what() << "\n";
        return 2;
    } catch (const pw::OutputError& e) {
        std::cerr << "patchwork: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "patchwork: internal error: " << e.what() << "\n";
        return 1;
    }
}
