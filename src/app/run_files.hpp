#pragma once
// Small file helpers of the driver: the files a run writes (for the one-run-per-folder rule and
// --overwrite), the run id, and probes.csv from the probe rows.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace ryushi {

// What a run writes into its output directory (frames/*.h5 besides), and what --overwrite
// removes: nothing else in the directory is touched.
inline const std::vector<std::string>& run_file_names() {
  static const std::vector<std::string> names{"summary.json", "particles.xdmf", "probes.csv",
                                              "profile.json", "trace.json",     "checkpoint.h5"};
  return names;
}

// The run files in `dir`, as "summary.json, checkpoint.h5, 21 frames" (empty: none).
inline std::string run_files_in(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::string found;
  std::error_code ec;
  for (auto& name : run_file_names())
    if (fs::exists(dir / name, ec)) found += (found.empty() ? "" : ", ") + name;
  std::size_t frames = 0;
  if (fs::is_directory(dir / "frames", ec))
    for (auto& e : fs::directory_iterator(dir / "frames", ec)) frames += e.path().extension() == ".h5";
  if (frames) found += (found.empty() ? "" : ", ") + std::to_string(frames) + " frames";
  return found;
}

inline void remove_run_files(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  for (auto& name : run_file_names()) fs::remove(dir / name);
  if (!fs::is_directory(dir / "frames")) return;
  for (auto& e : fs::directory_iterator(dir / "frames"))
    if (e.path().extension() == ".h5" || e.path().extension() == ".tmp") fs::remove(e.path());
}

// A run's id: random, so that two runs into one directory never share one.
inline std::uint64_t new_run_id() {
  std::random_device device;
  std::uint64_t id = (std::uint64_t(device()) << 32) ^ device();
  return id ? id : 1;  // 0 means "none"
}
inline std::string run_id_hex(std::uint64_t id) {
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(id));
  return text;
}

inline std::string probes_csv(const std::vector<ProbeSpec>& probes,
                              const std::vector<std::vector<double>>& rows) {
  std::ostringstream out;
  out.precision(10);
  out << "time";
  for (auto& p : probes) out << "," << p.name;
  out << "\n";
  for (auto& r : rows) {
    for (std::size_t k = 0; k < r.size(); ++k) out << (k ? "," : "") << r[k];
    out << "\n";
  }
  return out.str();
}

}  // namespace ryushi
