#include "base/input_error.h"

#include <cstdio>

std::string printable(const std::string& text, size_t maxBytes) {
  std::string result;
  for (size_t i = 0; i < text.size() && i < maxBytes; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      result += escaped;
    } else {
      result += char(c);
    }
  }
  if (text.size() > maxBytes) result += "... (" + std::to_string(text.size()) + " bytes)";
  return result;
}
