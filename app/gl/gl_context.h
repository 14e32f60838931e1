// One OpenGL 4.5 core context, created either headless (EGL surfaceless, falling back to the
// EGL device platform) or in a GLFW window. GL calls go through libepoxy either way.
#pragma once
#include <memory>
#include <string>

struct GLFWwindow;

class GlContext {
public:
  virtual ~GlContext() = default;

  // Returns nullptr and fills `error` (what was found, what to install) on failure.
  static std::unique_ptr<GlContext> createHeadless(std::string& error);
  static std::unique_ptr<GlContext> createWindow(int width, int height, const char* title,
                                                 std::string& error);

  virtual GLFWwindow* window() const { return nullptr; }
  std::string renderer() const;  // "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa ..."
  bool isSoftwareRenderer() const;  // llvmpipe/softpipe: GL_TIME_ELAPSED is not trustworthy
  int majorVersion() const;
  int minorVersion() const;
  bool isCoreProfile() const;
};

// Routes KHR_debug messages (medium and high severity) to stderr. Every GL_DEBUG_TYPE_ERROR
// of the API (not the shader compiler's, which reach their log) is also counted (glErrorCount), passed to the hook (tests: fail the running test), and,
// with PENUMBRA_GL_ERRORS_FATAL=1 in the environment (the tests that run the binary set it),
// ends the process with status 3 after printing it, so no GL error passes unnoticed.
void installGlDebugLog();
long glErrorCount();
// While set (between clearGlErrors and checkGlAllocation, gl_texture.h), GL errors are an
// allocation's refusal, which that check reports: printed, not counted, never fatal.
void setGlErrorsHandled(bool handled);
void setGlErrorHook(void (*hook)(const char* message));
