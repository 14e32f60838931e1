// A run refused as too long (a stage's cost estimate over its budget parameter, core/
// run_control.h) asks before anything more happens: "Run anyway" raises that budget just
// enough for this run (a longer one asks again), "Cancel" keeps the settings and the last
// image. While a run is under way, Esc cancels it (between stages, SSM tiles, reference tiles);
// a run that has lasted a second shows a "running" overlay over the last frame, with what it
// is doing and a Cancel button that does the same (drawn from the run's own checks, so it is
// live exactly when a cancel can take effect).
#pragma once
#include <memory>

struct UiState;

void drawRunBudgetModal(UiState& state);

// For its lifetime, the poll that lets Esc (or closing the window) cancel a run in progress
// and draws the "running" overlay: the key callback chained before ImGui's (installed after
// ImGui's GLFW backend, gone before it shuts down), what it saw, and the overlay's captured
// frame. One per window; the key and refresh callbacks find it through the window's user
// pointer.
struct GLFWwindow;
class RunCancelKeys {
public:
  explicit RunCancelKeys(GLFWwindow* window);
  ~RunCancelKeys();
  RunCancelKeys(const RunCancelKeys&) = delete;
  RunCancelKeys& operator=(const RunCancelKeys&) = delete;

  // Whether the overlay covered the screen since the last call: the next frame must be drawn.
  bool takeOverlayDrawn();
  // Whether the window was exposed (uncovered, restored) since the last call: its contents
  // must be drawn again. Set by the refresh callback.
  bool takeExposed();
  void onRefresh() { exposed_ = true; }
  // The key callback's: notes Esc, then passes the key on to the callback it replaced.
  void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

  struct Overlay;  // the frame captured when the run began (ui_run_budget.cpp)

private:
  GLFWwindow* window_;
  void (*previousKeyCallback_)(GLFWwindow*, int, int, int, int) = nullptr;
  bool escapePressed_ = false;
  bool exposed_ = false;
  std::unique_ptr<Overlay> overlay_;
};
// takeOverlayDrawn() of the window's RunCancelKeys (false without one).
bool takeRunOverlayDrawn(GLFWwindow* window);
// takeExposed() of the window's RunCancelKeys (false without one).
bool takeWindowExposed(GLFWwindow* window);
