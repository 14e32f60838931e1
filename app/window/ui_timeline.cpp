#include "window/ui_timeline.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "window/ui_session.h"

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

std::string drawTimeline(Session& session, float uiScale) {
  if (!session.animated()) return "";
  Animation& animation = session.rest.animation;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = 560 * uiScale;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f - width * 0.5f, display.y - 90 * uiScale),
                          ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(width, 0), ImGuiCond_FirstUseEver);
  std::string problem;
  if (ImGui::Begin("Timeline", nullptr, ImGuiWindowFlags_NoCollapse)) {
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
    if (next != session.time) problem = session.setTime(next);
    ImGui::Text("t = %.3f s  (%.3f of %.2f s, %s)", session.time, animation.cycleTime(session.time),
                animation.duration, repeatName(animation.repeat));
  }
  ImGui::End();
  return problem;
}
