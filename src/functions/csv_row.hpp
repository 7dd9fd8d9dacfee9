#pragma once
// One data row of a CSV file as numbers, for the readers of imported particles and motion
// tables: comma-separated, blanks around a number allowed, anything else an error.
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ryushi {

// Throws std::runtime_error("'FIELD' is not a finite number").
inline std::vector<double> csv_numbers(const std::string& line) {
  std::vector<double> values;
  std::stringstream fields(line);
  for (std::string field; std::getline(fields, field, ',');) {
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    while (end && (*end == ' ' || *end == '\t' || *end == '\r')) ++end;
    if (end == field.c_str() || *end != '\0' || !std::isfinite(value)) {
      field.erase(0, field.find_first_not_of(" \t"));
      throw std::runtime_error("'" + field + "' is not a finite number");
    }
    values.push_back(value);
  }
  return values;
}

// Whether a line holds nothing but blanks (skipped).
inline bool csv_blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

}  // namespace ryushi
