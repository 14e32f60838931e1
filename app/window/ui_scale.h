// The UI scale (projectors, high-DPI screens): the font atlas is rebuilt at 13 x scale pixels
// (so text stays sharp, unlike FontGlobalScale) and the style's sizes are scaled from the
// defaults (ImGuiStyle::ScaleAllSizes). Saved with the settings ("ui_scale").
#pragma once

constexpr float kMinUiScale = 0.75f, kMaxUiScale = 3.0f;

// Whether `scale` is a valid UI scale (finite, in [kMinUiScale, kMaxUiScale]).
bool validUiScale(float scale);
// Applies `scale` if it differs from `applied` (the scale applied last, 0 for none; the
// caller's state: UiState::appliedUiScale), which it then becomes; call between frames
// (before ImGui::NewFrame), after the OpenGL 3 backend is initialised.
void applyUiScale(float scale, float& applied);
