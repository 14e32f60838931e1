#include "core/param.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "base/input_error.h"

Param Param::boolean(std::string key, std::string doc, bool value) {
  return {std::move(key), std::move(doc), Type::Bool, double(value), 0, 1, {}};
}
Param Param::integer(std::string key, std::string doc, int value, int min, int max) {
  return {std::move(key), std::move(doc), Type::Int, double(value), double(min), double(max), {}};
}
Param Param::real(std::string key, std::string doc, double value, double min, double max) {
  return {std::move(key), std::move(doc), Type::Float, value, min, max, {}};
}
Param Param::choice(std::string key, std::string doc, std::vector<std::string> options,
                    int value) {
  const double last = double(options.size()) - 1;
  return {std::move(key), std::move(doc), Type::Enum, double(value), 0, last, std::move(options)};
}

Param Param::integerOrAuto(std::string key, std::string doc, int value, int min, int max) {
  Param param = integer(std::move(key), std::move(doc), value, min, max);
  param.allowsAuto = param.automatic = true;
  return param;
}
Param Param::choiceOrAuto(std::string key, std::string doc, std::vector<std::string> options,
                          int value) {
  Param param = choice(std::move(key), std::move(doc), std::move(options), value);
  param.allowsAuto = param.automatic = true;
  return param;
}

std::string Param::toString() const {
  if (automatic) return "auto";
  switch (type) {
    case Type::Bool: return asBool() ? "true" : "false";
    case Type::Int: return std::to_string(asInt());
    case Type::Enum: return asEnum();
    case Type::Float: {
      std::ostringstream out;
      out << value;
      return out.str();
    }
  }
  return "";
}

std::string Param::rangeText() const {
  std::ostringstream out;
  if (allowsAuto) out << "auto or ";
  switch (type) {
    case Type::Bool: return "true or false";
    case Type::Enum:
      out << "one of {";
      for (size_t i = 0; i < options.size(); ++i) out << (i ? ", " : "") << options[i];
      out << "}";
      return out.str();
    case Type::Int: out << "an integer in [" << int(min) << ", " << int(max) << "]"; break;
    case Type::Float: out << "a number in [" << min << ", " << max << "]"; break;
  }
  return out.str();
}

namespace {

// Plain decimal only: [+-] digits [. digits] [e [+-] digits]. strtod alone would also take
// hex ("0x4"), "inf", "nan" and leading spaces.
bool isDecimal(const std::string& text) {
  size_t i = 0, digits = 0;
  const auto run = [&] {
    size_t n = 0;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++n;
    return n;
  };
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  digits += run();
  if (i < text.size() && text[i] == '.') {
    ++i;
    digits += run();
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (run() == 0) return false;
  }
  return i == text.size();
}

}  // namespace

std::string Param::set(const std::string& text) {
  if (allowsAuto && text == "auto") {
    automatic = true;
    return "";
  }
  const bool wasAutomatic = automatic;
  automatic = false;  // a value given: fixed from now on (restored below if invalid)
  const std::string problem = setFixed(text);
  if (!problem.empty()) automatic = wasAutomatic;
  return problem;
}

std::string Param::setFixed(const std::string& text) {
  const auto invalid = [&] {
    std::string message(1, '\'');
    return message.append(printable(text)).append("' is not valid for ").append(key)
        .append(": expected ").append(rangeText());
  };
  switch (type) {
    case Type::Bool:
      if (text == "true" || text == "1" || text == "on") value = 1;
      else if (text == "false" || text == "0" || text == "off") value = 0;
      else return invalid();
      return "";
    case Type::Enum:
      for (size_t i = 0; i < options.size(); ++i)
        if (options[i] == text) { value = double(i); return ""; }
      return invalid();
    case Type::Int:
    case Type::Float: {
      if (!isDecimal(text)) return invalid();
      const double parsed = std::strtod(text.c_str(), nullptr);
      if (!std::isfinite(parsed)) return invalid();
      if (type == Type::Int && parsed != std::floor(parsed)) return invalid();
      if (parsed < min || parsed > max) return invalid();
      value = parsed;
      return "";
    }
  }
  return invalid();
}
