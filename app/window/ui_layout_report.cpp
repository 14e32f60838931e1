#include "window/ui_layout_report.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace {

// 1. Which glyph a quad shows: the glyph whose place in the atlas holds the quad's UVs
//    (a quad trimmed to a frame keeps a part of that place).
struct FoundGlyph {
  const ImFont* font = nullptr;
  const ImFontGlyph* glyph = nullptr;
};

FoundGlyph glyphAt(const ImFontAtlas& atlas, ImVec2 uv0, ImVec2 uv1) {
  constexpr float e = 1e-6f;
  for (const ImFont* font : atlas.Fonts)
    for (const ImFontGlyph& g : font->Glyphs)
      if (g.Visible && uv0.x >= g.U0 - e && uv1.x <= g.U1 + e && uv0.y >= g.V0 - e && uv1.y <= g.V1 + e)
        return {font, &g};
  return {};
}

void appendUtf8(std::string& text, unsigned codepoint) {
  char bytes[5] = {};
  ImTextCharToUtf8(bytes, codepoint);
  text += bytes;
}

// 2. Runs of text, glyph by glyph: a glyph continues the open run when it sits on the same
//    line and its pen position is where the last glyph's advance (plus whole spaces) ends.
struct RunBuilder {
  explicit RunBuilder(LayoutFrame& into) : frame(into) {}
  LayoutFrame& frame;
  LayoutText run;
  bool open = false;
  size_t framesBefore = 0;  // filled rectangles drawn before the open run's first glyph
  float lineTop = 0, penEnd = 0;

  void close() {
    if (open) frame.texts.push_back(run);
    open = false;
  }

  void add(const std::string& window, bool scrolls, bool scrollsX, const FoundGlyph& found, const LayoutRect& drawn,
           const ImVec2& uv0, const ImVec2& uv1, const LayoutRect& clip) {
    const ImFontGlyph& g = *found.glyph;
    // Pixels per unit of UV: from the quad where it has a size, else the font's own size.
    const float sx = drawn.x1 - drawn.x0 > 0.5f ? (drawn.x1 - drawn.x0) / (uv1.x - uv0.x) : (g.X1 - g.X0) / (g.U1 - g.U0);
    const float sy = drawn.y1 - drawn.y0 > 0.5f ? (drawn.y1 - drawn.y0) / (uv1.y - uv0.y) : (g.Y1 - g.Y0) / (g.V1 - g.V0);
    const float scale = g.X1 > g.X0 ? sx * (g.U1 - g.U0) / (g.X1 - g.X0) : 1.0f;  // drawn size / font size
    const LayoutRect whole{drawn.x0 - (uv0.x - g.U0) * sx, drawn.y0 - (uv0.y - g.V0) * sy,
                           drawn.x1 + (g.U1 - uv1.x) * sx, drawn.y1 + (g.V1 - uv1.y) * sy};
    const LayoutRect visible{std::max(drawn.x0, clip.x0), std::max(drawn.y0, clip.y0),
                             std::min(drawn.x1, clip.x1), std::min(drawn.y1, clip.y1)};
    const float cutX = (whole.x1 - whole.x0) - std::max(0.0f, visible.x1 - visible.x0);
    const float cutY = (whole.y1 - whole.y0) - std::max(0.0f, visible.y1 - visible.y0);
    const float pen = whole.x0 - g.X0 * scale, top = whole.y0 - g.Y0 * scale;
    const ImFontGlyph* space = found.font->FindGlyphNoFallback(' ');
    const float spaceAdvance = (space ? space->AdvanceX : found.font->FallbackAdvanceX) * scale;
    int spaces = -1;  // how many spaces lie between the open run and this glyph; -1: not its run
    if (open && run.window == window && std::abs(top - lineTop) < 0.05f && run.clip.x0 == clip.x0 &&
        run.clip.y0 == clip.y0 && run.clip.x1 == clip.x1 && run.clip.y1 == clip.y1) {
      const float gap = (pen - penEnd) / spaceAdvance;
      if (gap > -0.01f && gap < 8.5f && std::abs(gap - std::round(gap)) < 0.02f) spaces = int(std::round(gap));
    }
    if (spaces < 0) {
      close();
      open = true;
      run = LayoutText{};
      run.window = window;
      run.windowScrolls = scrolls;
      run.windowScrollsX = scrollsX;
      run.clip = clip;
      run.extent = {pen, top, pen, top + found.font->FontSize * scale};
      run.ink = visible;
      run.framesBefore = framesBefore;
      spaces = 0;
    }
    run.text.append(size_t(spaces), ' ');
    appendUtf8(run.text, g.Codepoint);
    penEnd = pen + g.AdvanceX * scale;
    lineTop = top;
    run.extent.x1 = penEnd;
    if (visible.x1 > visible.x0 && visible.y1 > visible.y0) {
      if (run.ink.x1 <= run.ink.x0 || run.ink.y1 <= run.ink.y0) run.ink = visible;
      run.ink = {std::min(run.ink.x0, visible.x0), std::min(run.ink.y0, visible.y0),
                 std::max(run.ink.x1, visible.x1), std::max(run.ink.y1, visible.y1)};
    }
    // ImGui snaps text and clip rectangles to pixels: half a pixel is not a cut.
    if (cutX > 0.5f) run.cutX += cutX;
    if (cutY > 0.5f) run.cutY += cutY;
  }
};

// 2b. ImGui's own ellipsis (RenderTextEllipsis: tab labels too long for the tab) is three
//     dots drawn one pixel (x the scale) apart, not at the font's advance: three runs of a
//     single '.' in a row on one line. The run it follows was cut short.
void markEllipses(std::vector<LayoutText>& texts) {
  const auto dot = [&](size_t i) { return i < texts.size() && texts[i].text == "."; };
  for (size_t i = 0; i + 2 < texts.size(); ++i) {
    if (!dot(i) || !dot(i + 1) || !dot(i + 2)) continue;
    const LayoutText &a = texts[i], &b = texts[i + 1], &c = texts[i + 2];
    const float gap = b.ink.x0 - a.ink.x1;
    const bool together = a.window == c.window && a.extent.y0 == b.extent.y0 && b.extent.y0 == c.extent.y0 &&
                          gap >= 0 && gap < 0.25f * (a.extent.y1 - a.extent.y0) &&
                          std::abs((c.ink.x0 - b.ink.x1) - gap) < 0.1f;
    if (!together) continue;
    const bool follows = i > 0 && texts[i - 1].window == a.window && texts[i - 1].extent.y0 == a.extent.y0 &&
                         std::abs(texts[i - 1].extent.x1 - a.extent.x0) < (a.extent.y1 - a.extent.y0);
    texts[follows ? i - 1 : i].ellipsis = true;
    i += 2;
  }
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

// 3. Every draw command's quads: glyphs (font texture) into runs, other textures as images.
LayoutFrame measureLayout(const ImDrawData& data) {
  LayoutFrame frame;
  const ImGuiContext& context = *ImGui::GetCurrentContext();
  std::map<const ImDrawList*, const ImGuiWindow*> owners;
  for (const ImGuiWindow* window : context.Windows) owners[window->DrawList] = window;
  const ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
  RunBuilder runs(frame);
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    const auto owner = owners.find(&list);
    const std::string window = owner != owners.end() ? owner->second->Name : (list._OwnerName ? list._OwnerName : "?");
    // A child window (a table) inside a scrolling panel is cut at the panel's edge too; a
    // window made to scroll sideways (a table with ImGuiTableFlags_ScrollX) is cut at its
    // edges by design.
    bool scrolls = false, scrollsX = false;
    for (const ImGuiWindow* w = owner != owners.end() ? owner->second : nullptr; w; w = w->ParentWindow) {
      scrolls |= w->ScrollMax.y > 0;
      scrollsX |= w->ScrollMax.x > 0 || (w->Flags & ImGuiWindowFlags_HorizontalScrollbar);
      if (!(w->Flags & ImGuiWindowFlags_ChildWindow)) break;
    }
    std::vector<LayoutRect> filled;  // this list's filled rectangles, in drawing order
    size_t firstRun = frame.texts.size();
    const auto assignFrames = [&] {  // to the runs closed since the last call
      for (; firstRun < frame.texts.size(); ++firstRun) {
        LayoutText& run = frame.texts[firstRun];
        for (size_t f = run.framesBefore; f-- > 0;)
          if (filled[f].x0 <= run.ink.x0 + 0.5f && filled[f].y0 <= run.ink.y0 + 0.5f &&
              filled[f].x1 >= run.ink.x1 - 0.5f && filled[f].y1 >= run.ink.y1 - 0.5f) {
            run.frame = filled[f];
            run.hasFrame = true;
            break;
          }
      }
    };
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      runs.close();
      if (cmd.UserCallback) continue;
      const LayoutRect clip{cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w};
      const bool font = cmd.TextureId == atlas.TexID;
      for (unsigned i = 0; i + 6 <= cmd.ElemCount;) {
        const ImDrawIdx* idx = &list.IdxBuffer[int(cmd.IdxOffset + i)];
        const bool quad = idx[1] == idx[0] + 1 && idx[2] == idx[0] + 2 && idx[3] == idx[0] &&
                          idx[4] == idx[0] + 2 && idx[5] == idx[0] + 3;
        if (!quad) {  // another shape: triangles; whatever it is, it ends a run
          runs.close();
          i += 3;
          continue;
        }
        const ImDrawVert* v = &list.VtxBuffer[int(cmd.VtxOffset + idx[0])];
        i += 6;
        const bool rect = v[0].pos.y == v[1].pos.y && v[2].pos.y == v[3].pos.y && v[0].pos.x == v[3].pos.x &&
                          v[1].pos.x == v[2].pos.x && v[0].uv.y == v[1].uv.y && v[0].uv.x == v[3].uv.x;
        if (!rect) {
          runs.close();
          continue;
        }
        const LayoutRect drawn{v[0].pos.x, v[0].pos.y, v[2].pos.x, v[2].pos.y};
        if (!font) {
          frame.images.push_back({window, drawn, clip});
          continue;
        }
        const ImVec2 uv0 = v[0].uv, uv1 = v[2].uv;
        const FoundGlyph found = uv1.x >= uv0.x && uv1.y > uv0.y ? glyphAt(atlas, uv0, uv1) : FoundGlyph{};
        if (!found.glyph) {  // a filled rectangle (the white texel) or a line's texture
          runs.close();
          const ImU32 rgb = v[0].col & 0x00FFFFFFu;
          if (uv0.x == uv1.x && uv0.y == uv1.y && rgb != (ImGui::GetColorU32(ImGuiCol_SliderGrab) & 0x00FFFFFFu) &&
              rgb != (ImGui::GetColorU32(ImGuiCol_SliderGrabActive) & 0x00FFFFFFu))
            filled.push_back(drawn);
          continue;
        }
        runs.framesBefore = filled.size();
        runs.add(window, scrolls, scrollsX, found, drawn, uv0, uv1, clip);
      }
    }
    runs.close();
    assignFrames();
  }
  markEllipses(frame.texts);
  return frame;
}

#include "window/views/ui_view_colorbar.h"

void printLayout(const UiState& state, const std::string& label) {
  const ImGuiContext& context = *ImGui::GetCurrentContext();
  for (const ImGuiWindow* window : context.Windows) {
    if (!window->WasActive || window->Hidden) continue;  // not drawn in the last frame
    // Whole pixels: ImGui rounds text widths up to whole pixels, and panel edges may lie
    // between pixels, so a line that fits can reach up to one pixel past a fractional edge.
    const float overflow = std::floor(std::max(0.0f, window->DC.CursorMaxPos.x - window->WorkRect.Max.x));
    std::printf("layout %s: window %s at %.0f %.0f size %.0f %.0f contents %.0f %.0f overflow %.0f\n",
                label.c_str(), window->Name, window->Pos.x, window->Pos.y, window->Size.x,
                window->Size.y, window->ContentSize.x, window->ContentSize.y, overflow);
  }
  if (const ImDrawData* data = ImGui::GetDrawData(); data && data->Valid) {
    const LayoutFrame frame = measureLayout(*data);
    for (const LayoutText& t : frame.texts)
      std::printf("layout %s: text %s at %.1f %.1f size %.1f %.1f clip %.1f %.1f %.1f %.1f ink %.1f %.1f "
                  "%.1f %.1f frame %.1f %.1f %.1f %.1f cut %.1f %.1f scrolls %d %d ellipsis %d %s\n",
                  label.c_str(), t.window.c_str(), t.extent.x0, t.extent.y0, t.extent.x1 - t.extent.x0,
                  t.extent.y1 - t.extent.y0, t.clip.x0, t.clip.y0, t.clip.x1, t.clip.y1, t.ink.x0,
                  t.ink.y0, t.ink.x1, t.ink.y1, t.frame.x0, t.frame.y0, t.frame.x1, t.frame.y1, t.cutX, t.cutY, t.windowScrollsX ? 1 : 0, t.windowScrolls ? 1 : 0, t.ellipsis ? 1 : 0,
                  quoted(t.text).c_str());
    for (const LayoutImage& image : frame.images)
      std::printf("layout %s: image %s at %.1f %.1f size %.1f %.1f clip %.1f %.1f %.1f %.1f\n",
                  label.c_str(), image.window.c_str(), image.rect.x0, image.rect.y0,
                  image.rect.x1 - image.rect.x0, image.rect.y1 - image.rect.y0, image.clip.x0,
                  image.clip.y0, image.clip.x1, image.clip.y1);
  }
  printColorBars(state, label);
  std::fflush(stdout);
}
