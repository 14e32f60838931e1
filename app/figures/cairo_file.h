// One cairo file (PNG, SVG or PDF) written whole or not at all: drawn onto a surface for a
// temporary name, cairo's status checked, then renamed into place (plots and figure sheets).
#pragma once
#include <cairo.h>

#include <filesystem>
#include <functional>

// `make` creates the surface for the temporary file name; `png`: the surface is an image
// surface to be written with cairo_surface_write_to_png. Throws std::runtime_error naming
// the file when cairo reports a failure (nothing is left behind).
void writeCairoFile(const std::filesystem::path& path,
                    const std::function<cairo_surface_t*(const char*)>& make,
                    const std::function<void(cairo_t*)>& draw, bool png);
