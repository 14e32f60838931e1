#include "window_app.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "gl_context.h"
#include "image_export.h"
#include "pipeline.h"
#include "scene_builtin.h"
#include "texture_view.h"

namespace {

void helpMarker(const std::string& text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text.c_str());
}

// Draws a parameter from its declaration; returns true when it changed.
bool drawParam(Param& param) {
  bool changed = false;
  const char* label = param.key.c_str();
  switch (param.type) {
    case Param::Type::Bool: {
      bool value = param.asBool();
      if ((changed = ImGui::Checkbox(label, &value))) param.value = value;
      break;
    }
    case Param::Type::Int: {
      int value = param.asInt();
      if ((changed = ImGui::SliderInt(label, &value, int(param.min), int(param.max))))
        param.value = value;
      break;
    }
    case Param::Type::Float: {
      float value = param.asFloat();
      if ((changed = ImGui::SliderFloat(label, &value, float(param.min), float(param.max))))
        param.value = value;
      break;
    }
    case Param::Type::Enum: {
      int value = param.asInt();
      if (ImGui::BeginCombo(label, param.asEnum().c_str())) {
        for (size_t i = 0; i < param.options.size(); ++i)
          if (ImGui::Selectable(param.options[i].c_str(), value == int(i))) {
            param.value = double(i);
            changed = true;
          }
        ImGui::EndCombo();
      }
      break;
    }
  }
  helpMarker(param.doc + "\nRange: " + param.rangeText());
  return changed;
}

void saveScreenshot(GLFWwindow* window, const std::string& path) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  std::vector<std::uint8_t> rgb(size_t(width) * height * 3), flipped(rgb.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  const size_t row = size_t(width) * 3;
  for (int y = 0; y < height; ++y)
    std::copy_n(&rgb[size_t(height - 1 - y) * row], row, &flipped[size_t(y) * row]);
  writePng(path, flipped, width, height);
}

}  // namespace

int runWindow(const WindowOptions& options) {
  std::vector<std::string> warnings;
  Scene scene;
  try {
    scene = loadScene(options.scene, warnings);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "penumbra: %s\n", error.what());
    return 2;
  }
  std::unique_ptr<GlContext> context;  // declared first: GL objects die before it
  Pipeline pipeline;
  for (const std::string& assignment : options.sets)
    if (std::string problem = pipeline.set(assignment); !problem.empty()) {
      std::fprintf(stderr, "penumbra: --set %s\n", problem.c_str());
      return 2;
    }
  std::string error;
  context = GlContext::createWindow(options.width, options.height, "penumbra", error);
  if (!context) {
    std::fprintf(stderr, "penumbra: %s\nWithout a display, run: penumbra export --scene %s --out out\n",
                 error.c_str(), options.scene.c_str());
    return 1;
  }
  GLFWwindow* window = context->window();
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");

  int result = 0;
  try {
    GpuScene gpuScene(scene);
    Frame frame(scene, gpuScene, pipeline);
    TextureView view;
    std::string selected = "composite.color";
    int framesRendered = 0;
    while (!glfwWindowShouldClose(window)) {
      glfwPollEvents();
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      const float panelWidth = 340.0f;
      frame.eyeWidth = std::max(64, int(width - panelWidth));
      frame.eyeHeight = std::max(64, height);
      pipeline.run(frame);

      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      ImGui::SetNextWindowPos({0, 0});
      ImGui::SetNextWindowSize({panelWidth, float(height)});
      ImGui::Begin("Pipeline", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
      ImGui::TextWrapped("Scene '%s', %zu triangles", scene.name.c_str(), scene.triangleCount());
      for (const auto& stage : pipeline.stages()) {
        const auto& times = pipeline.lastTimes();
        double ms = 0;
        for (const StageTime& time : times)
          if (time.stage == stage->name()) ms = time.milliseconds;
        if (ImGui::CollapsingHeader((stage->name() + "  (" + std::to_string(int(ms + 0.5)) +
                                     " ms)###" + stage->name()).c_str(),
                                    ImGuiTreeNodeFlags_DefaultOpen)) {
          ImGui::TextWrapped("%s  [thesis %s]", stage->summary().c_str(),
                             stage->thesisSection().c_str());
          for (const Output& output : stage->outputs()) {
            const std::string key = stage->name() + "." + output.name;
            if (ImGui::RadioButton(key.c_str(), selected == key)) selected = key;
            helpMarker(output.doc);
          }
          ImGui::PushID(stage->name().c_str());
          for (Param& param : stage->params()) drawParam(param);
          ImGui::PopID();
        }
      }
      ImGui::End();

      ImGui::SetNextWindowPos({panelWidth, 0});
      ImGui::SetNextWindowSize({float(width) - panelWidth, float(height)});
      ImGui::Begin("View", nullptr,
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoTitleBar);
      if (frame.has(selected)) {
        const size_t dot = selected.find('.');
        const Output& output = pipeline.stage(selected.substr(0, dot)).output(selected.substr(dot + 1));
        const GlTexture& shown = view.render(frame.input(selected), output.display);
        const ImVec2 avail = ImGui::GetContentRegionAvail();
        const float scale = std::min(avail.x / shown.width(), avail.y / shown.height());
        ImGui::Image(reinterpret_cast<ImTextureID>(std::uintptr_t(shown.id())),
                     {shown.width() * scale, shown.height() * scale}, {0, 1}, {1, 0});
      }
      ImGui::End();

      ImGui::Render();
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, width, height);
      glClearColor(0.1f, 0.1f, 0.1f, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      ++framesRendered;
      if (!options.screenshot.empty() && framesRendered >= options.frames) {
        saveScreenshot(window, options.screenshot);
        std::printf("penumbra: wrote %s after %d frames\n", options.screenshot.c_str(),
                    framesRendered);
        break;
      }
      glfwSwapBuffers(window);
    }
  } catch (const std::exception& failure) {
    std::fprintf(stderr, "penumbra: %s\n", failure.what());
    result = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return result;
}
