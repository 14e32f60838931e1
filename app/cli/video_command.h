// `penumbra export --time-range A:B --fps F`: an animation's frames, MP4s and GIFs
// (app/export/video_export.h; docs/decisions/130-video-export.md).
#pragma once

struct ExportOptions;

int runVideoExport(const ExportOptions& options);
