#pragma once
// A [[metric]]'s reference table, a side file of the scene (tools/reference/*.csv): two numeric
// columns after optional '#' comment lines and a header line, the first increasing.
#include <string>
#include <utility>
#include <vector>

namespace ryushi {

// Throws SceneError "file:line: message" on a malformed line.
std::vector<std::pair<double, double>> read_reference_table(const std::string& path);

}  // namespace ryushi
