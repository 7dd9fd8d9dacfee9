#pragma once
// Helpers shared by the tests: scratch directories, scene files, CSV and JSON look-ups.
#include <doctest/doctest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace ryushi::test {

namespace fs = std::filesystem;

inline fs::path source_dir() {
  return RYUSHI_SOURCE_DIR;
}
inline std::string scene_path(const std::string& name) {
  return (source_dir() / "scenes" / name).string();
}

// A fresh directory under the build tree, removed at construction.
inline fs::path scratch(const std::string& name) {
  fs::path p = fs::current_path() / "scratch" / name;
  fs::remove_all(p);
  fs::create_directories(p.parent_path());
  return p;
}

// A fresh scratch directory whose name no other test process or call uses (pid and counter):
// for helpers that several test cases call while ctest runs them as parallel processes.
inline fs::path unique_scratch(const std::string& prefix) {
  static std::atomic<int> counter{0};
  return scratch(prefix + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
}

// |value / expected - 1| <= tolerance, written without the division (expected = 0 asks for 0;
// NaN fails). Not doctest's Approx(expected).epsilon(tolerance): that passes when
// |value - expected| < tolerance * (1 + max(|value|, |expected|)), so for |expected| << 1 the
// bound is about `tolerance` in absolute terms (a "5%" check on 1.12e-5 m accepted +-0.05 m),
// and near 1 it is about twice the tolerance (test audit round three, issue 50).
inline bool within_relative(double value, double expected, double tolerance) {
  return std::abs(value - expected) <= tolerance * std::abs(expected);
}

inline std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_text(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

// A WCSPH scene file's text with the Riemann dissipation in place of its artificial viscosity and
// delta-SPH keys (which dissipation = "riemann" refuses): those lines dropped, the key added
// after the method's name.
inline std::string with_riemann_dissipation(const std::string& scene) {
  std::istringstream in(scene);
  std::string out, line;
  while (std::getline(in, line)) {
    const bool dropped = line.rfind("delta =", 0) == 0 || line.rfind("artificial_viscosity", 0) == 0;
    if (!dropped) out += line + "\n";
    if (line.rfind("name = \"wcsph\"", 0) == 0) out += "dissipation = \"riemann\"\n";
  }
  REQUIRE(out.find("dissipation = \"riemann\"") != std::string::npos);
  return out;
}

// The head of a small 2D scene ([scene], [domain], [particles], [time]) that the bad-input tests
// complete with the blocks under test.
inline std::string small_scene_head() {
  return R"([scene]
dimension = 2
[domain]
min = [-0.2, -0.2]
max = [1.2, 1.2]
[particles]
spacing = 0.05
[time]
end = 0.1
)";
}

// A 2D scene in the unit box with one fluid block and no walls; `extra` is appended (TOML).
inline std::string block_scene(const std::string& fluid_min, const std::string& fluid_max, double end,
                               const std::string& extra = "") {
  return "[scene]\ndimension = 2\n[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[particles]\nspacing = 0.05\n"
         "[time]\nend = " +
         std::to_string(end) + "\n[[fluid]]\nmin = " + fluid_min + "\nmax = " + fluid_max + "\n" + extra;
}

// Columns of a CSV with a header row. Asking for a column the file does not have, or one with no
// rows, fails the test (REQUIRE): a check on a missing probe must not pass on an empty vector.
struct Csv {
  std::map<std::string, std::vector<double>> columns;
  std::string file;
  const std::vector<double>& operator[](const std::string& name) const {
    auto it = columns.find(name);
    REQUIRE_MESSAGE(it != columns.end(), file << " has no column '" << name << "'");
    REQUIRE_MESSAGE(!it->second.empty(), file << ": column '" << name << "' has no rows");
    return it->second;
  }
  std::size_t count(const std::string& name) const { return columns.count(name); }
};
inline Csv read_csv(const fs::path& p) {
  std::ifstream in(p);
  REQUIRE_MESSAGE(in.good(), "cannot open " << p);
  std::string line;
  // The header follows any '#' comment lines (tools/reference/ tables carry their source so).
  while (std::getline(in, line) && (line.empty() || line[0] == '#')) {
  }
  std::vector<std::string> names;
  std::stringstream hs(line);
  for (std::string n; std::getline(hs, n, ',');) names.push_back(n);
  Csv csv;
  csv.file = p.string();
  for (auto& n : names) csv.columns[n];
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::size_t k = 0;
    for (std::string v; std::getline(ls, v, ',') && k < names.size(); ++k)
      csv.columns[names[k]].push_back(std::strtod(v.c_str(), nullptr));
  }
  return csv;
}

// The first "key": value in a JSON text (flat look-up is enough for summary.json). A missing key
// fails the test (REQUIRE): a key that disappears must not read as 0 or "".
inline std::string json_raw(const std::string& json, const std::string& key) {
  auto at = json.find("\"" + key + "\": ");
  REQUIRE_MESSAGE(at != std::string::npos, "no key '" << key << "' in the JSON");
  at += key.size() + 4;
  if (json[at] == '"') return json.substr(at + 1, json.find('"', at + 1) - at - 1);
  return json.substr(at, json.find_first_of(",\n}", at) - at);
}
inline double json_number(const std::string& json, const std::string& key) {
  auto raw = json_raw(json, key);
  char* end = nullptr;
  double value = std::strtod(raw.c_str(), &end);
  REQUIRE_MESSAGE(end != raw.c_str(), "key '" << key << "' is not a number: " << raw);
  return value;
}

// A [least, largest] pair of summary.json's diagnostics_range.
inline std::pair<double, double> json_range(const std::string& json, const std::string& key) {
  auto at = json.find("\"diagnostics_range\"");
  REQUIRE_MESSAGE(at != std::string::npos, "no diagnostics_range in the JSON");
  at = json.find("\"" + key + "\": [", at);
  REQUIRE_MESSAGE(at != std::string::npos, "no range '" << key << "' in diagnostics_range");
  char* end = nullptr;
  const double least = std::strtod(json.c_str() + json.find('[', at) + 1, &end);
  const double largest = std::strtod(end + 1, nullptr);  // past the comma
  return {least, largest};
}

// Runs a shell command; returns its exit status and captures stderr+stdout.
struct CommandResult {
  int code;
  std::string output;
};
inline CommandResult run_command(const std::string& cmd) {
  // ctest runs test cases as parallel processes in one directory: the log name must be unique
  // across processes (pid) and within one (counter). std::rand() is not: every process starts
  // from the same seed, and two tests once read each other's output.
  static std::atomic<int> counter{0};
  fs::path log = fs::current_path() / "scratch" /
                 ("cmd_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".log");
  fs::create_directories(log.parent_path());
  int status = std::system((cmd + " > " + log.string() + " 2>&1").c_str());
  int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::string out = read_text(log);
  fs::remove(log);
  return {code, out};
}

// Writes the scene text to dir/s.toml, runs `ryushi check --write-initial` on it and returns the
// frame it wrote (the generated particles before any step).
inline fs::path initial_frame(const fs::path& dir, const std::string& scene_text) {
  write_text(dir / "s.toml", scene_text);
  auto r = run_command(std::string(RYUSHI_BINARY) + " check " + (dir / "s.toml").string() +
                       " --write-initial " + (dir / "init").string());
  REQUIRE_MESSAGE(r.code == 0, r.output);
  return dir / "init" / "frames" / "frame_00000.h5";
}

}  // namespace ryushi::test
