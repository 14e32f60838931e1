#include "window/ui_widgets.h"
#include "window/views/ui_texture_view.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>

#include "window/ui_camera.h"
#include "window/ui_frame_change.h"
#include "window/ui_light_gesture.h"
#include "window/views/ui_nbuffer_hover.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/views/ui_view_colorbar.h"
#include "window/views/ui_view_toolbar.h"

namespace {

glm::vec2 toGlm(ImVec2 v) { return {v.x, v.y}; }
ImVec2 toIm(glm::vec2 v) { return {v.x, v.y}; }

// Screen rectangle of the inclusive texel window [lo, hi].
void texelRect(const ViewTransform& t, glm::ivec2 lo, glm::ivec2 hi, glm::vec2 origin,
               glm::vec2 size, ImVec2& topLeft, ImVec2& bottomRight) {
  topLeft = toIm(t.screenFromTexel({float(lo.x), float(hi.y + 1)}, origin, size));
  bottomRight = toIm(t.screenFromTexel({float(hi.x + 1), float(lo.y)}, origin, size));
}

// 1a. Settings follow the output (before the toolbar draws them).
void syncSettings(UiState& state, ViewPanel& view, const GlTexture& texture) {
  if (view.settingsFor != view.output) {
    if (const Output* output = state.session.outputOf(view.output))
      view.settings = defaultViewSettings(*output, texture.channelCount());
    view.settingsFor = view.output;
    view.fitPending = true;
    // Integer data (counts, ids) rarely lies in [0, 1]: start from its actual range.
    if (texture.isInteger() && view.settings.colormap != Colormap::Categorical)
      view.autofitPending = true;
  }
  if (view.autofitPending) {
    autofitView(view, texture);
    view.autofitPending = false;
  }
}

// 1b. The transform follows the texture's size.
void placeImage(ViewPanel& view, const GlTexture& texture, glm::vec2 regionSize) {
  const glm::ivec2 size{texture.width(), texture.height()};
  glm::ivec2& lastSize = view.lastTextureSize;
  if (view.fitPending || lastSize.x == 0 || (view.fitted && (size != lastSize || regionSize != view.regionSize))) {
    view.transform.fit(glm::vec2(size), regionSize);
    view.fitPending = false;
    view.fitted = true;
  } else if (size != lastSize) {  // same picture at another resolution (preview, resize)
    const float ratio = float(size.x) / float(lastSize.x);
    view.transform.zoom /= ratio;
    view.transform.center *= glm::vec2(size) / glm::vec2(lastSize);
  }
  lastSize = size;
}

// 1c. "Show on the N-buffer": the view zooms onto the ray's windows and points.
void frameOverlays(const UiState& state, ViewPanel& view, glm::ivec2 size, glm::vec2 regionSize) {
  glm::vec2 lo{1e30f}, hi{-1e30f};
  for (const ViewOverlayShape& shape : state.views.overlays)
    if (shape.space == size) {
      lo = glm::min(lo, glm::min(shape.a, shape.b));
      hi = glm::max(hi, glm::max(shape.a, shape.b));
    }
  if (lo.x > hi.x) return;  // not drawn yet (the pipeline records the pixel first)
  const glm::vec2 extent = glm::max(hi - lo, glm::vec2(40)) * 1.4f;  // some context around
  view.transform.zoom = std::clamp(std::min(regionSize.x / extent.x, regionSize.y / extent.y), kMinZoom, 32.0f);
  view.transform.center = 0.5f * (lo + hi);
  view.fitted = false;
  view.frameOverlays = false;
}

// 2. Image, texel grid, overlay rectangles, pick marker, all clipped to the region.
void drawImage(const UiState& state, const ViewPanel& view, const GlTexture& display,
               glm::vec2 origin, glm::vec2 regionSize, std::optional<glm::ivec2> hover) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ViewTransform& t = view.transform;
  const glm::ivec2 size{display.width(), display.height()};
  draw->PushClipRect(toIm(origin), toIm(origin + regionSize), true);
  draw->AddRectFilled(toIm(origin), toIm(origin + regionSize), IM_COL32(24, 24, 28, 255));
  ImVec2 topLeft, bottomRight;
  texelRect(t, {0, 0}, size - 1, origin, regionSize, topLeft, bottomRight);
  // GL row 0 is the bottom row: v = 1 at the top of the screen.
  draw->AddImage(reinterpret_cast<ImTextureID>(std::uintptr_t(display.id())), topLeft,
                 bottomRight, {0, 1}, {1, 0});
  if (t.zoom >= kGridZoom) {
    glm::ivec2 lo, hi;
    t.visibleTexels(regionSize, size, lo, hi);
    const ImU32 grid = IM_COL32(128, 128, 128, 90);
    for (int x = lo.x; x <= hi.x; ++x)
      draw->AddLine(toIm(t.screenFromTexel({float(x), float(lo.y)}, origin, regionSize)),
                    toIm(t.screenFromTexel({float(x), float(hi.y)}, origin, regionSize)), grid);
    for (int y = lo.y; y <= hi.y; ++y)
      draw->AddLine(toIm(t.screenFromTexel({float(lo.x), float(y)}, origin, regionSize)),
                    toIm(t.screenFromTexel({float(hi.x), float(y)}, origin, regionSize)), grid);
  }
  for (const ViewOverlayShape& shape : state.views.overlays) {
    if (shape.space != size) continue;
    const ImVec2 a = toIm(t.screenFromTexel(shape.a, origin, regionSize));
    const ImVec2 b = toIm(t.screenFromTexel(shape.b, origin, regionSize));
    if (shape.dot > 0) {  // a dark ring keeps white dots visible on the empty (white) map
      draw->AddCircleFilled(a, shape.dot + 1.5f, IM_COL32(0, 0, 0, 200));
      draw->AddCircleFilled(a, shape.dot, shape.color);
    }
    else if (shape.line) draw->AddLine(a, b, shape.color, 2);
    else draw->AddRect({std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)},
                       shape.color, 0, 0, 1.5f);
  }
  // N-buffer: the level-0 window the hovered texel of this level summarises (a min-max
  // mipmap's level is shown at its own size: a texel is its cell there).
  if (hover && view.output == recordingInput(state.session.pipeline, "levels") && view.settings.layer > 0 &&
      state.session.frame && state.session.frame->has(view.output) &&
      state.session.frame->texture(view.output).isArray() && hover->x >= 0 &&
      hover->y >= 0 && hover->x < size.x && hover->y < size.y) {
    glm::ivec2 lo, hi;
    nbufferWindow(view.settings.layer, *hover, size, lo, hi);
    texelRect(t, lo, hi, origin, regionSize, topLeft, bottomRight);
    // Magenta: no N-buffer level's colour (ui_trace_panel.cpp levelColor), so it never
    // reads as one of the ray's visited windows.
    draw->AddRect(topLeft, bottomRight, IM_COL32(255, 0, 255, 255), 0, 0, 2);
  }
  if (state.session.frame && size == glm::ivec2(state.session.frame->eyeWidth, state.session.frame->eyeHeight))
    drawLightOutline(state, view, size, origin, regionSize);
  if (state.views.pick && state.views.pickSpace == size) {
    texelRect(t, *state.views.pick, *state.views.pick, origin, regionSize, topLeft, bottomRight);
    const ImVec2 centre{0.5f * (topLeft.x + bottomRight.x), 0.5f * (topLeft.y + bottomRight.y)};
    const float arm = std::max(6.0f, 0.5f * (bottomRight.x - topLeft.x) + 4);
    draw->AddRect(topLeft, bottomRight, IM_COL32(255, 255, 0, 255));
    draw->AddLine({centre.x - arm - 6, centre.y}, {centre.x - arm, centre.y}, IM_COL32(255, 255, 0, 255), 2);
    draw->AddLine({centre.x + arm, centre.y}, {centre.x + arm + 6, centre.y}, IM_COL32(255, 255, 0, 255), 2);
    draw->AddLine({centre.x, centre.y - arm - 6}, {centre.x, centre.y - arm}, IM_COL32(255, 255, 0, 255), 2);
    draw->AddLine({centre.x, centre.y + arm}, {centre.x, centre.y + arm + 6}, IM_COL32(255, 255, 0, 255), 2);
  }
  draw->PopClipRect();
}

// 3. Mouse over the image region (an invisible button owns it).
bool handleMouse(UiState& state, int index, glm::ivec2 size, glm::vec2 origin,
                 glm::vec2 regionSize) {
  ViewPanel& view = state.views.panels[index];
  ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  const glm::vec2 mouse = toGlm(io.MousePos);
  // Alt: the mouse moves the light instead (eye-sized views: the scene as the eye sees it).
  const bool eyeSized = state.session.frame && size == glm::ivec2(state.session.frame->eyeWidth, state.session.frame->eyeHeight);
  if (io.KeyAlt && eyeSized) return handleLightMouse(state, view, size, origin, regionSize);
  bool movingCamera = false;
  if (hovered && io.MouseWheel != 0) {
    if (io.KeyCtrl) {
      dollyCamera(state.session.scene.camera, std::pow(0.9f, io.MouseWheel));
    } else {
      view.transform.zoomAbout(std::pow(1.25f, io.MouseWheel), mouse, origin, regionSize);
      view.fitted = false;
      if (state.views.linked) state.views.linkFrom(index);
    }
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    view.transform.pan(toGlm(io.MouseDelta));
    view.fitted = false;
    if (state.views.linked) state.views.linkFrom(index);
  }
  if (ImGui::IsItemDeactivated() && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
      io.MouseDragMaxDistanceSqr[0] < io.MouseDragThreshold * io.MouseDragThreshold && hovered)
    state.views.setPick(view.transform.texelAt(mouse, origin, regionSize), size);
  const glm::vec2 delta = toGlm(io.MouseDelta);
  const bool pressedHere = ImGui::IsItemActive();
  if (pressedHere && ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
    movingCamera = true;
    if (io.KeyShift) panCamera(state.session.scene.camera, -delta.x / regionSize.x, delta.y / regionSize.y);
    else orbitCamera(state.session.scene.camera, -delta.x * 0.01f, -delta.y * 0.01f);
  }
  if (pressedHere && ImGui::IsMouseDown(ImGuiMouseButton_Middle)) {
    movingCamera = true;
    panCamera(state.session.scene.camera, -delta.x / regionSize.x, delta.y / regionSize.y);
  }
  return movingCamera;
}

// The first of `texts` that fits the line (a small view, a large UI scale), else the last:
// the readout is one reserved line and never runs past the view.
std::string fitting(std::initializer_list<std::string> texts) {
  const float width = ImGui::GetContentRegionAvail().x;
  for (const std::string& text : texts)
    if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  return *(texts.end() - 1);
}

// 4. The readout line: hovered texel (else the pick) with its raw values.
void drawReadout(const UiState& state, const ViewPanel& view, const GlTexture& texture,
                 std::optional<glm::ivec2> hover) {
  const glm::ivec2 size{texture.width(), texture.height()};
  std::optional<glm::ivec2> at = hover;
  const char* what = "hover";
  if (!at && state.views.pick && state.views.pickSpace == size) {
    at = state.views.pick;
    what = "pick";
  }
  if (!at || at->x < 0 || at->y < 0 || at->x >= size.x || at->y >= size.y) {
    const std::string extent = std::to_string(size.x) + "x" + std::to_string(size.y) + (texture.isArray() ? " (array)" : "");
    ImGui::TextDisabled("%s", fitting({extent + "  click: pick, drag: pan, wheel: zoom, right drag: orbit, Alt: light",
                                       extent + "  F1: help", extent}).c_str());
    return;
  }
  const std::array<float, 4> texel = readTexel(texture, at->x, at->y, view.settings.layer);
  const std::vector<std::string> names = shownChannelNames(state, view);
  std::string text;
  char value[64];
  for (int c = 0; c < texture.channelCount(); ++c) {
    const std::string name = size_t(c) < names.size() ? names[size_t(c)] : std::string(1, "RGBA"[c]);
    std::snprintf(value, sizeof value, "%s%s=%.6g", c ? "  " : "", name.c_str(), texel[size_t(c)]);
    text += value;
  }
  // Image coordinates (row 0 at the top, as the PNGs and `penumbra trace --pixel`).
  std::string where = "(";  // appended, not "(" + ...: GCC 12's -Wrestrict false positive (bug 105329)
  where.append(std::to_string(at->x)).append(", ").append(std::to_string(size.y - 1 - at->y)).append(")");
  ImGui::TextUnformatted(fitting({what + (" " + where) + ": " + text, where + " " + text, text}).c_str());
}

// 4a. What the image shows beyond what the draw data says (the display texture's contents:
//     its source, the run that wrote it, the settings that coloured it).
void mixShownContent(UiState& state, const ViewPanel& view, const GlTexture& source) {
  std::uint64_t& hash = state.shownContent;
  const ViewSettings& s = view.settings;
  mixHash(hash, source.id());
  mixHash(hash, std::uint64_t(state.session.pipelineRuns));
  mixHash(hash, std::hash<std::string>{}(view.output + "-" + view.minus));
  mixHash(hash, view.clipNegative);
  for (bool on : s.channels) mixHash(hash, on);
  for (float v : {s.black, s.white}) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    mixHash(hash, bits);
  }
  mixHash(hash, std::uint64_t(s.colormap));
  mixHash(hash, s.overlay);
  mixHash(hash, std::uint64_t(std::int64_t(s.layer)));
}

// 4b. Why a view has nothing to show: its output has not been run yet (it runs next
//     frame), the last run failed, or the last run did not write it.
std::string notShownReason(const UiState& state, const ViewPanel& view) {
  if (!state.session.runError.empty())
    return "'" + view.output + "' was not written: the last run failed (the log says why)";
  if (state.needsRun()) return "'" + view.output + "': not run yet";
  return "'" + view.output + "' was not written by the last run";
}

}  // namespace

// 5. Child window: toolbar, image region, readout.
bool drawTextureView(UiState& state, int index, ImVec2 size) {
  ViewPanel& view = state.views.panels[index];
  const bool several = state.views.shownViews() > 1;
  const bool active = state.views.activeView == index && several;
  const char letter[2] = {"ABCD"[index], 0};
  if (active) ImGui::PushStyleColor(ImGuiCol_Border, IM_COL32(230, 180, 60, 255));
  ImGui::BeginChild((std::string("view_") + letter).c_str(), size, true,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  if (active) ImGui::PopStyleColor();
  if (ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows) &&
      (ImGui::IsMouseClicked(ImGuiMouseButton_Left) || ImGui::IsMouseClicked(ImGuiMouseButton_Right)))
    state.views.activeView = index;
  // The eye size for "fit view" depends on the view's size only, not on how the toolbar of
  // the current output wraps, so choosing another output never re-runs the pipeline. The
  // reserve is the toolbar's widest case (about 1400 pixels of controls) plus the readout.
  const ImVec2 whole = ImGui::GetContentRegionAvail();
  const bool compact = state.views.layout == ViewLayout::Grid;  // tools behind "..." (one line)
  const float toolbarLines = compact ? 1.0f : std::max(2.0f, std::ceil(uiPixels(1400) / std::max(whole.x, 1.0f)));
  // A window too small for the toolbar still gets a (tiny) region: zero would read as "no
  // layout yet" and the pipeline (and a script waiting for its first run) would never start.
  view.eyeRegion = glm::max(glm::vec2(whole.x, whole.y - toolbarLines * ImGui::GetFrameHeightWithSpacing() -
                                                   ImGui::GetTextLineHeightWithSpacing()),
                            glm::vec2(1));
  if (several) {
    ImGui::TextColored(active ? ImVec4(0.9f, 0.7f, 0.25f, 1) : ImVec4(0.6f, 0.6f, 0.6f, 1), "%s", letter);
    ImGui::SameLine();
  }
  std::string problem;
  const GlTexture* texture = shownTexture(state, view, &problem);
  if (texture) syncSettings(state, view, *texture);
  const std::string shownOutput = view.output, shownMinus = view.minus;
  drawViewToolbar(state, view, texture, compact);
  if (view.output != shownOutput || view.minus != shownMinus) {  // picked in the toolbar just now
    problem.clear();
    texture = shownTexture(state, view, &problem);  // usually none: the next frame runs it
    if (texture) syncSettings(state, view, *texture);
  }
  const float readoutHeight = ImGui::GetTextLineHeightWithSpacing();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const glm::vec2 regionSize{std::max(avail.x, 16.0f), std::max(avail.y - readoutHeight, 16.0f)};
  bool movingCamera = false;
  if (!texture) {
    view.regionSize = regionSize;
    ImGui::Dummy(toIm(regionSize));
    ImGui::TextDisabled("%s", problem.empty() ? notShownReason(state, view).c_str() : problem.c_str());
  } else {
    placeImage(view, *texture, regionSize);
    if (view.frameOverlays) frameOverlays(state, view, {texture->width(), texture->height()}, regionSize);
    view.regionSize = regionSize;
    const glm::vec2 origin = toGlm(ImGui::GetCursorScreenPos());
    view.regionOrigin = origin;
    // While any popup is open (an output list over the image), the popup owns the mouse: in
    // the popup's first frame ImGui has not placed it yet and would let the image below take
    // a click or a wheel.
    const bool popupOpen = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
    ImGui::BeginDisabled(popupOpen);
    ImGui::InvisibleButton("image", toIm(regionSize),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    ImGui::EndDisabled();
    const glm::ivec2 textureSize{texture->width(), texture->height()};
    movingCamera = handleMouse(state, index, textureSize, origin, regionSize);
    std::optional<glm::ivec2> hover;
    if (ImGui::IsItemHovered())
      hover = view.transform.texelAt(toGlm(ImGui::GetIO().MousePos), origin, regionSize);
    updateAutoRange(state, view, *texture);
    drawImage(state, view, view.renderer.render(*texture, view.settings, state.session.pipelineRuns), origin, regionSize, hover);
    mixShownContent(state, view, *texture);
    drawViewColorBar(state, view, *texture, origin, regionSize);
    drawReadout(state, view, *texture, hover);
  }
  ImGui::EndChild();
  return movingCamera;
}
