#include "support/refusal.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "base/input_error.h"

std::string refusalOf(const std::string& what, const std::function<void()>& load) {
  try {
    load();
  } catch (const InputError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << what << ": not an InputError: " << error.what();
    return error.what();
  }
  ADD_FAILURE() << what << " loaded but should be refused";
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
