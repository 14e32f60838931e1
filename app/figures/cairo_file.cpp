#include "figures/cairo_file.h"

#include <stdexcept>
#include <system_error>

void writeCairoFile(const std::filesystem::path& path,
                    const std::function<cairo_surface_t*(const char*)>& make,
                    const std::function<void(cairo_t*)>& draw, bool png) {
  const std::filesystem::path temporary = path.string() + ".tmp";
  cairo_surface_t* surface = make(temporary.c_str());
  cairo_t* cr = cairo_create(surface);
  draw(cr);
  cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  if (png && status == CAIRO_STATUS_SUCCESS)
    status = cairo_surface_write_to_png(surface, temporary.c_str());
  cairo_surface_finish(surface);
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error("cannot write " + path.string() + ": " + cairo_status_to_string(status));
  }
  std::filesystem::rename(temporary, path);
}
