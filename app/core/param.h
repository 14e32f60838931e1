// A stage parameter, declared once (key, doc, default, range): the UI draws it with a (?)
// marker from `doc`, `--set stage.key=value` sets it, lessons and tests sweep it.
#pragma once
#include <string>
#include <vector>

struct Param {
  enum class Type { Bool, Int, Float, Enum };
  std::string key;  // "bias", addressed as "stage.bias"
  std::string doc;
  Type type = Type::Float;
  double value = 0, min = 0, max = 1;  // Bool: 0/1, Enum: option index
  std::vector<std::string> options;    // Enum only
  // `auto` (stages/shared_inputs/light/auto_settings.h; docs/accuracy.md): a parameter that allows it takes the
  // value "auto" (the stage chooses from the scene and view); a number or option clears it.
  bool allowsAuto = false;
  bool automatic = false;

  static Param boolean(std::string key, std::string doc, bool value);
  static Param integer(std::string key, std::string doc, int value, int min, int max);
  static Param real(std::string key, std::string doc, double value, double min, double max);
  static Param choice(std::string key, std::string doc, std::vector<std::string> options,
                      int value);
  // The same, also accepting "auto", which they start as.
  static Param integerOrAuto(std::string key, std::string doc, int value, int min, int max);
  static Param choiceOrAuto(std::string key, std::string doc, std::vector<std::string> options,
                            int value);

  bool asBool() const { return value != 0; }
  int asInt() const { return int(value); }
  float asFloat() const { return float(value); }
  const std::string& asEnum() const { return options.at(size_t(value)); }

  std::string toString() const;
  std::string rangeText() const;  // "[0.001, 1]", "one of {linear, hierarchical}", ...
  // Parses and range-checks `text`; returns an error message naming the valid range, or "".
  std::string set(const std::string& text);

private:
  std::string setFixed(const std::string& text);
};
