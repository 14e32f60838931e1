// The window's fixed layout, recomputed each frame from its size and the UI scale.
// Panels scale with the window, within limits, and the views keep at
// least half the window's width (kMinViewsShare). When the two side panels, each at least
// 220 px x the UI scale, would leave the views less, they collapse into one column on the
// left whose tabs hold the pipeline, the inspector and the chart. A playing lesson's panel
// sits below the views (its height taken from theirs), never over them.
#pragma once

inline constexpr float kMinViewsShare = 0.5f;

struct Layout {
  float width, height, left, right, status, lesson;
  bool stacked;  // one side column (left) with every side tab; right == 0
  float timeline = 0;  // an animated scene's timeline strip, between the views and the lesson
  float centerWidth() const { return width - left - right; }
  float panelHeight() const { return height - status; }
  float viewsHeight() const { return panelHeight() - lesson - timeline; }
};

// The layout of a width x height window at uiScale, with a lesson strip and an animated
// scene's timeline strip of the given heights below the views (0: none).
Layout layoutFor(float width, float height, float uiScale, float lessonHeight, float timelineHeight);
