#include "gl/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

const char* kInstallHint =
    "penumbra needs OpenGL 4.5 core. On Debian 12 install the Mesa drivers: "
    "apt-get install libgl1-mesa-dri libegl1-mesa-dev (llvmpipe provides 4.5 without a GPU).";

bool versionIsEnough(const GlContext& context, std::string& error) {
  if (context.majorVersion() * 10 + context.minorVersion() >= 45 && context.isCoreProfile())
    return true;
  error = "found OpenGL " + std::to_string(context.majorVersion()) + "." +
          std::to_string(context.minorVersion()) +
          (context.isCoreProfile() ? " core" : " (not core)") + " on '" + context.renderer() +
          "'. " + kInstallHint;
  return false;
}

class EglContext final : public GlContext {
public:
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  ~EglContext() override {
    if (display == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    eglTerminate(display);
  }
};

// 1. Surfaceless Mesa platform; 2. the first EGL device that initialises.
EGLDisplay openEglDisplay(std::string& tried) {
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA,
                                                EGL_DEFAULT_DISPLAY, nullptr);
  if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  tried += "EGL_PLATFORM_SURFACELESS_MESA unavailable; ";
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration")) {
    tried += "EGL_EXT_device_enumeration unavailable";
    return EGL_NO_DISPLAY;
  }
  EGLint count = 0;
  eglQueryDevicesEXT(0, nullptr, &count);
  std::vector<EGLDeviceEXT> devices(count);
  eglQueryDevicesEXT(count, devices.data(), &count);
  for (EGLDeviceEXT device : devices) {
    display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  }
  tried += std::to_string(count) + " EGL devices, none initialised";
  return EGL_NO_DISPLAY;
}

class GlfwContext final : public GlContext {
public:
  GLFWwindow* handle = nullptr;
  GLFWwindow* window() const override { return handle; }
  ~GlfwContext() override {
    if (handle) glfwDestroyWindow(handle);
    glfwTerminate();
  }
};

}  // namespace

std::unique_ptr<GlContext> GlContext::createHeadless(std::string& error) {
  auto result = std::make_unique<EglContext>();
  std::string tried;
  result->display = openEglDisplay(tried);
  if (result->display == EGL_NO_DISPLAY) {
    error = "no headless EGL display (" + tried + "). " + kInstallHint;
    return nullptr;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    error = "EGL cannot bind the desktop OpenGL API. " + std::string(kInstallHint);
    return nullptr;
  }
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_CONTEXT_OPENGL_DEBUG,
                               EGL_TRUE, EGL_NONE};
  // EGL_KHR_no_config_context: no surface, so no config is needed.
  result->context = eglCreateContext(result->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                     attributes);
  if (result->context == EGL_NO_CONTEXT ||
      !eglMakeCurrent(result->display, EGL_NO_SURFACE, EGL_NO_SURFACE, result->context)) {
    char code[32];
    std::snprintf(code, sizeof code, "0x%04x", eglGetError());
    error = "EGL could not create an OpenGL 4.5 core context (EGL error " + std::string(code) +
            ", vendor '" + std::string(eglQueryString(result->display, EGL_VENDOR) ?: "?") +
            "'). " + kInstallHint;
    return nullptr;
  }
  if (!versionIsEnough(*result, error)) return nullptr;
  installGlDebugLog();
  return result;
}

std::unique_ptr<GlContext> GlContext::createWindow(int width, int height, const char* title,
                                                   std::string& error) {
  if (!glfwInit()) {
    error = "GLFW could not initialise (no display? set DISPLAY or use `penumbra export`)";
    return nullptr;
  }
  auto result = std::make_unique<GlfwContext>();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  result->handle = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (!result->handle) {
    const char* description = nullptr;
    glfwGetError(&description);
    error = "GLFW could not open an OpenGL 4.5 core window (" +
            std::string(description ? description : "unknown") + "). " + kInstallHint;
    return nullptr;
  }
  glfwMakeContextCurrent(result->handle);
  glfwSwapInterval(0);
  if (!versionIsEnough(*result, error)) return nullptr;
  installGlDebugLog();
  return result;
}

std::string GlContext::renderer() const {
  auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
  };
  return text(GL_RENDERER) + " | " + text(GL_VERSION);
}

bool GlContext::isSoftwareRenderer() const {
  const std::string name = renderer();
  return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
}

int GlContext::majorVersion() const { return epoxy_gl_version() / 10; }
int GlContext::minorVersion() const { return epoxy_gl_version() % 10; }
bool GlContext::isCoreProfile() const {
  GLint mask = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  return (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
}

namespace {
long gErrorCount = 0;
void (*gErrorHook)(const char*) = nullptr;
bool gErrorsHandled = false;
}  // namespace

long glErrorCount() { return gErrorCount; }
void setGlErrorsHandled(bool handled) { gErrorsHandled = handled; }
void setGlErrorHook(void (*hook)(const char* message)) { gErrorHook = hook; }

void installGlDebugLog() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_LOW, 0, nullptr, GL_FALSE);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr,
                        GL_FALSE);
  glDebugMessageCallback(
      [](GLenum source, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
         const void*) {
        std::fprintf(stderr, "[gl %s%s] %s\n",
                     severity == GL_DEBUG_SEVERITY_HIGH ? "high" : "medium",
                     type == GL_DEBUG_TYPE_ERROR ? " error" : "", message);
        // A shader that does not compile is reported with its log (ShaderProgram::reload),
        // and kept running on its last good build: not a GL error.
        if (type != GL_DEBUG_TYPE_ERROR || source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
        if (gErrorsHandled) return;  // an allocation's refusal, reported by its check
        ++gErrorCount;
        if (gErrorHook) gErrorHook(message);
        const char* fatal = std::getenv("PENUMBRA_GL_ERRORS_FATAL");
        if (fatal && std::string(fatal) == "1") {
          std::fprintf(stderr, "penumbra: GL error with PENUMBRA_GL_ERRORS_FATAL=1: exiting\n");
          std::fflush(stderr);
          std::_Exit(3);
        }
      },
      nullptr);
}
