#include "window/ui_timeline.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "window/ui_record.h"
#include "window/ui_session.h"
#include "window/ui_state.h"

bool timelinePlaysLive(const Session& session, bool scripted) {
  return session.playing && session.animated() && !scripted;
}

std::string advanceTimeline(Session& session, TimelineClock& clock, double now) {
  const double elapsed = clock.last < 0 ? 0 : now - clock.last;
  clock.last = now;
  if (!session.playing || !session.animated()) return "";
  // A long stall (a slow run, the window dragged) moves time by at most a quarter second,
  // so the animation does not jump past what the views showed.
  const double step = std::min(elapsed, 0.25) * session.speed;
  if (step == 0) return "";
  std::string problem = session.setTime(session.time + step);
  if (!problem.empty()) session.playing = false;
  return problem;
}

float timelineHeight(const Session& session) {
  if (!session.animated()) return 0;
  const ImGuiStyle& style = ImGui::GetStyle();
  return 2 * style.WindowPadding.y + ImGui::GetFrameHeightWithSpacing() +
         ImGui::GetTextLineHeightWithSpacing();
}

std::string drawTimeline(UiState& state, float uiScale, float x, float y, float width, float height) {
  Session& session = state.session;
  if (!session.animated()) return "";
  Animation& animation = session.rest.animation;
  ImGui::SetNextWindowPos({x, y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({width, height}, ImGuiCond_Always);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoTitleBar;
  std::string problem;
  if (ImGui::Begin("###timeline", nullptr, flags)) {
    double next = session.time;
    if (ImGui::Button(session.playing ? "Pause" : "Play")) session.playing = !session.playing;
    ImGui::SameLine();
    if (ImGui::Button("<")) next -= kTimelineStep;
    ImGui::SameLine();
    if (ImGui::Button(">")) next += kTimelineStep;
    ImGui::SameLine();
    // Scrubbing shows the time within one cycle of the animation.
    float cycle = float(animation.cycleTime(session.time));
    ImGui::SetNextItemWidth(220 * uiScale);
    if (ImGui::SliderFloat("##time", &cycle, 0.0f, float(animation.duration), "%.2f s")) next = cycle;
    ImGui::SameLine();
    float speed = float(session.speed);
    ImGui::SetNextItemWidth(70 * uiScale);
    if (ImGui::DragFloat("speed", &speed, 0.05f, -4.0f, 4.0f, "%.2fx")) session.speed = speed;
    ImGui::SameLine();
    int repeat = int(animation.repeat);
    const char* names[] = {"loop", "ping-pong", "once"};
    ImGui::SetNextItemWidth(90 * uiScale);
    if (ImGui::Combo("##repeat", &repeat, names, 3)) {
      animation.repeat = Repeat(repeat);
      next = animation.cycleTime(session.time);  // the same pose, in the new mode's terms
    }
    ImGui::SameLine();
    drawRecordButton(state);  // the views over a time range, as frames and videos (ui_record.h)
    if (next != session.time) problem = session.setTime(next);
    ImGui::Text("t = %.3f s  (%.3f of %.2f s, %s)", session.time, animation.cycleTime(session.time),
                animation.duration, repeatName(animation.repeat));
  }
  ImGui::End();
  return problem;
}
