#include "ui/platform/x11_present.hpp"

#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstdlib>
#include <cstring>

#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>

namespace pw::ui {
inline namespace platform {

struct X11Presenter::Impl {
    Display* display = nullptr;
    Window window = 0;
    Visual* visual = nullptr;
    int depth = 0;
    GC gc = nullptr;
    // MIT-SHM (local X servers): the frame is copied into a shared segment the server reads
    // directly; where attaching fails (a remote display) plain XPutImage is used.
    bool shm = false;
    XShmSegmentInfo seg{};
    XImage* shmImage = nullptr;
    VkExtent2D shmExtent{0, 0};
    void releaseShm();
    bool makeShm(VkExtent2D extent);
};

namespace {
bool g_xerror = false;
int recordXError(Display*, XErrorEvent*) {
    g_xerror = true;
    return 0;
}
}  // namespace

void X11Presenter::Impl::releaseShm() {
    if (!shmImage) return;
    XShmDetach(display, &seg);
    XSync(display, False);
    shmImage->data = nullptr;
    XDestroyImage(shmImage);
    shmdt(seg.shmaddr);
    shmImage = nullptr;
    shmExtent = {0, 0};
}

bool X11Presenter::Impl::makeShm(VkExtent2D extent) {
    releaseShm();
    XImage* img = XShmCreateImage(display, visual, unsigned(depth), ZPixmap, nullptr, &seg, extent.width, extent.height);
    if (!img) return false;
    seg.shmid = shmget(IPC_PRIVATE, size_t(img->bytes_per_line) * img->height, IPC_CREAT | 0600);
    if (seg.shmid < 0) {
        XDestroyImage(img);
        return false;
    }
    seg.shmaddr = img->data = static_cast<char*>(shmat(seg.shmid, nullptr, 0));
    shmctl(seg.shmid, IPC_RMID, nullptr);  // freed once both sides have detached
    if (seg.shmaddr == reinterpret_cast<char*>(-1)) {
        img->data = nullptr;
        XDestroyImage(img);
        return false;
    }
    seg.readOnly = True;
    // A remote server cannot attach: that arrives as an X error, caught here.
    g_xerror = false;
    XSync(display, False);
    auto* old = XSetErrorHandler(recordXError);
    XShmAttach(display, &seg);
    XSync(display, False);
    XSetErrorHandler(old);
    if (g_xerror) {
        img->data = nullptr;
        XDestroyImage(img);
        shmdt(seg.shmaddr);
        return false;
    }
    shmImage = img;
    shmExtent = extent;
    return true;
}

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
    impl->shm = XShmQueryExtension(display);
    return std::unique_ptr<X11Presenter>(new X11Presenter(std::move(impl)));
}

X11Presenter::X11Presenter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

X11Presenter::~X11Presenter() {
    impl_->releaseShm();
    XFreeGC(impl_->display, impl_->gc);
}

void X11Presenter::present(const uint8_t* bgra, VkExtent2D extent, uint32_t rowBytes) {
    Impl& m = *impl_;
    if (m.shm && (m.shmExtent.width != extent.width || m.shmExtent.height != extent.height)) m.shm = m.makeShm(extent);
    if (m.shm) {
        XImage* img = m.shmImage;
        for (uint32_t y = 0; y < extent.height; ++y)
            std::memcpy(img->data + size_t(y) * size_t(img->bytes_per_line), bgra + size_t(y) * rowBytes, size_t(extent.width) * 4);
        XShmPutImage(m.display, m.window, m.gc, img, 0, 0, 0, 0, extent.width, extent.height, False);
        XSync(m.display, False);  // the server has read the segment: it may be written again
        return;
    }
    // The XImage only borrows the pixels (data is detached again before XDestroyImage frees it).
    XImage* img = XCreateImage(m.display, m.visual, unsigned(m.depth), ZPixmap, 0, const_cast<char*>(reinterpret_cast<const char*>(bgra)),
                               extent.width, extent.height, 32, int(rowBytes));
    if (!img) return;
    XPutImage(m.display, m.window, m.gc, img, 0, 0, 0, 0, extent.width, extent.height);
    img->data = nullptr;
    XDestroyImage(img);
    XSync(m.display, False);  // one frame in flight, like FIFO
}

}  // namespace platform
}  // namespace pw::ui
