// A results.csv or loop.csv read back as rows of fields (quoted fields may hold commas): the
// bench tests check the files the bench wrote, not the bench's own structures.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

inline std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(file, line);) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) { fields.push_back(field); field.clear(); }
      else field += c;
    }
    fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}
