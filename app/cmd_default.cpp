// `patchwork [FILE]` with no sub-command: opens the interactive editor on FILE (default: the
// built-in teapot). Without a display it says so and exits 2.
#include <iostream>

#include "app/commands.hpp"

#ifdef PATCHWORK_HAVE_EDITOR
#include "ui/editor/editor.hpp"
#endif

namespace pw::app {

int runDefault(const std::string& file) {
#ifdef PATCHWORK_HAVE_EDITOR
    return pw::ui::runEditor(file);
#else
    (void)file;
    std::cerr << "patchwork: this build has no editor (configure with -DPATCHWORK_BUILD_EDITOR=ON); use `patchwork render FILE "
                 "-o out.png` for headless images\n";
    return 2;
#endif
}

}  // namespace pw::app
