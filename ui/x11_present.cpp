#include "x11_present.hpp"

#include <cstdlib>
#include <cstring>

#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#include <X11/Xutil.h>

namespace pw::ui {

struct X11Presenter::Impl {
    Display* display = nullptr;
    Window window = 0;
    Visual* visual = nullptr;
    int depth = 0;
    GC gc = nullptr;
};

std::unique_ptr<X11Presenter> X11Presenter::create(GLFWwindow* window) {
    if (const char* p = std::getenv("PATCHWORK_PRESENT"); p && std::strcmp(p, "swapchain") == 0) return nullptr;
    Display* display = glfwGetX11Display();
    const Window xw = display ? glfwGetX11Window(window) : 0;
    if (!display || !xw) return nullptr;
    XWindowAttributes wa{};
    if (!XGetWindowAttributes(display, xw, &wa) || !wa.visual) return nullptr;
    // B8G8R8A8 in memory is a 32-bit little-endian pixel 0xAARRGGBB: TrueColor with these masks.
    const Visual* v = wa.visual;
    if (v->c_class != TrueColor || v->red_mask != 0xff0000 || v->green_mask != 0xff00 || v->blue_mask != 0xff ||
        (wa.depth != 24 && wa.depth != 32) || ImageByteOrder(display) != LSBFirst)
        return nullptr;
    auto impl = std::make_unique<Impl>();
    impl->display = display;
    impl->window = xw;
    impl->visual = wa.visual;
    impl->depth = wa.depth;
    impl->gc = XCreateGC(display, xw, 0, nullptr);
    if (!impl->gc) return nullptr;
    return std::unique_ptr<X11Presenter>(new X11Presenter(std::move(impl)));
}

X11Presenter::X11Presenter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

X11Presenter::~X11Presenter() { XFreeGC(impl_->display, impl_->gc); }

void X11Presenter::present(const uint8_t* bgra, VkExtent2D extent, uint32_t rowBytes) {
    Impl& m = *impl_;
    // The XImage only borrows the pixels (data is detached again before XDestroyImage frees it).
    XImage* img = XCreateImage(m.display, m.visual, unsigned(m.depth), ZPixmap, 0, const_cast<char*>(reinterpret_cast<const char*>(bgra)),
                               extent.width, extent.height, 32, int(rowBytes));
    if (!img) return;
    XPutImage(m.display, m.window, m.gc, img, 0, 0, 0, 0, extent.width, extent.height);
    img->data = nullptr;
    XDestroyImage(img);
    XSync(m.display, False);  // one frame in flight, like FIFO
}

}  // namespace pw::ui
