// Headless EGL context: the Mesa surfaceless platform (llvmpipe on this machine) or the EGL
// device platform (an NVIDIA GPU without a display server).
#include "gl/egl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstring>
#include <string>
#include <vector>

#include "gl/debug_output.h"
#include "gl/gl_error.h"

namespace cutaway::gl {
namespace {

bool has_extension(const char* list, const char* name) {
    if (list == nullptr) return false;
    const std::size_t length = std::strlen(name);
    for (const char* at = std::strstr(list, name); at != nullptr; at = std::strstr(at + 1, name)) {
        const bool starts = at == list || at[-1] == ' ';
        const bool ends = at[length] == '\0' || at[length] == ' ';
        if (starts && ends) return true;
    }
    return false;
}

std::string egl_error_name(EGLint code) {
    switch (code) {
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "EGL error " + std::to_string(code);
    }
}

/// What the EGL device search found: the first device that is real hardware (not Mesa's
/// software device), or none and why (for the error message of `--egl-platform device`).
struct DeviceSearch {
    EGLDeviceEXT device = EGL_NO_DEVICE_EXT;
    std::string why_none;
};

DeviceSearch find_hardware_device() {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    // EGL_EXT_device_base is the older name of device_enumeration + device_query together.
    const bool enumeration = has_extension(client, "EGL_EXT_device_enumeration") || has_extension(client, "EGL_EXT_device_base");
    if (!enumeration || !has_extension(client, "EGL_EXT_platform_device"))
        return {EGL_NO_DEVICE_EXT, std::string("the EGL client extensions lack ") +
                                       (enumeration ? "EGL_EXT_platform_device" : "EGL_EXT_device_enumeration") +
                                       " (client extensions: " + (client ? client : "none") + ")"};
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0)
        return {EGL_NO_DEVICE_EXT, "eglQueryDevicesEXT lists no device (" + egl_error_name(eglGetError()) + ")"};
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (!eglQueryDevicesEXT(count, devices.data(), &count))
        return {EGL_NO_DEVICE_EXT, "eglQueryDevicesEXT failed listing " + std::to_string(count) + " devices"};
    for (EGLint d = 0; d < count; ++d) {
        const char* device_extensions = eglQueryDeviceStringEXT(devices[std::size_t(d)], EGL_EXTENSIONS);
        if (!has_extension(device_extensions, "EGL_MESA_device_software")) return {devices[std::size_t(d)], {}};
    }
    return {EGL_NO_DEVICE_EXT, std::to_string(count) + " EGL device(s), all Mesa software devices"};
}

class EglContext final : public GlContext {
public:
    explicit EglContext(const ContextOptions& options) {
        const std::string& wanted = options.egl_platform;
        if (wanted != "auto" && wanted != "surfaceless" && wanted != "device")
            throw GlError("EGL platform '" + wanted + "': expected auto, surfaceless or device");
        const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (client == nullptr) throw GlError("no EGL client library (libEGL) could be loaded");

        if (wanted != "surfaceless") {
            const DeviceSearch search = find_hardware_device();
            if (search.device != EGL_NO_DEVICE_EXT) {
                display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, search.device, nullptr);
                platform_ = "egl/device";
            } else if (wanted == "device") {
                throw GlError("EGL platform 'device': no hardware EGL device found: " + search.why_none);
            }
        }
        if (display_ == EGL_NO_DISPLAY) {
            if (!has_extension(client, "EGL_MESA_platform_surfaceless"))
                throw GlError("EGL: neither a hardware device nor EGL_MESA_platform_surfaceless is available "
                              "(install libegl-mesa0 and libgl1-mesa-dri)");
            display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            platform_ = "egl/surfaceless";
        }
        if (display_ == EGL_NO_DISPLAY) throw GlError("EGL: could not open a display on " + platform_);
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor))
            throw GlError("EGL: eglInitialize failed on " + platform_ + ": " + egl_error_name(eglGetError()));
        initialized_ = true;
        if (!eglBindAPI(EGL_OPENGL_API)) throw GlError("EGL: desktop OpenGL API not available on " + platform_);

        const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                            EGL_NONE};
        EGLConfig config = nullptr;
        EGLint config_count = 0;
        const bool no_config = has_extension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context");
        if (!no_config && (!eglChooseConfig(display_, config_attributes, &config, 1, &config_count) || config_count == 0))
            throw GlError("EGL: no OpenGL-renderable config on " + platform_);

        const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                             EGL_CONTEXT_MINOR_VERSION, 5,
                                             EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                             EGL_CONTEXT_OPENGL_DEBUG, options.debug_output ? EGL_TRUE : EGL_FALSE,
                                             EGL_NONE};
        context_ = eglCreateContext(display_, no_config ? EGL_NO_CONFIG_KHR : config, EGL_NO_CONTEXT, context_attributes);
        if (context_ == EGL_NO_CONTEXT)
            throw GlError("EGL: no OpenGL 4.5 core context on " + platform_ + ": " + egl_error_name(eglGetError()));
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw GlError("EGL: cannot make the context current without a surface on " + platform_ + ": " +
                          egl_error_name(eglGetError()));
        if (epoxy_gl_version() < 45)
            throw GlError("EGL: context reports OpenGL " + std::to_string(epoxy_gl_version()) + ", need 45");
        if (options.debug_output) enable_debug_output();
    }

    ~EglContext() override {
        if (context_ != EGL_NO_CONTEXT) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display_, context_);
        }
        if (initialized_) eglTerminate(display_);
    }
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    std::string platform() const override { return platform_; }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    bool initialized_ = false;
    std::string platform_;
};

}  // namespace

std::unique_ptr<GlContext> create_egl_context(const ContextOptions& options) {
    return std::make_unique<EglContext>(options);
}

}  // namespace cutaway::gl
